// The composite V-cycle (composite_impl.hpp): ghost filling from the recipes, relaxation of a tier's
// patches (points, or zebra lines along runs and origin shells), residuals, quadratic interpolation
// up from the coarse windows, the leaf residual and the restriction of the solution.
#include <algorithm>
#include <cmath>
#include <limits>

#include "boundary_ghosts.hpp"
#include "composite_impl.hpp"
#include "level_ops.hpp"
#include "line_relaxation.hpp"
#include "line_relaxation_3d.hpp"
#include "point_relaxation.hpp"
#include "remnant/comm_counters.hpp"
#include "shell_relaxation.hpp"

namespace remnant::xcfc {

void CompositeMultigrid::Impl::fill(int t, const ScalarEquation& eq, const std::array<double, 64>& par, const Tier::Split* mine_only) {
  Tier& T = tiers[static_cast<std::size_t>(t)];
  if (t == 0) {
    fill_ghosts(T.patches[0], eq, T.patches[0].u, false);
    return;
  }
  const Recipes& R = recipes_for(eq);
  // The patches' arrays by (tier, patch) looked up once per fill, not per term: evaluate's sum
  // (Recipes: the same terms in the same order, so the same bits) with two loads per term fewer.
  fill_arrays.resize(tiers.size());
  for (std::size_t s = 0; s < tiers.size(); ++s) {
    fill_arrays[s].resize(tiers[s].patches.size());
    for (std::size_t p = 0; p < tiers[s].patches.size(); ++p) fill_arrays[s][p] = tiers[s].patches[p].u.data();
  }
  const StoredTerm* terms = R.terms.data();
  auto fill_patch = [&](std::size_t p) {
    const auto& recipes = R.ghosts[static_cast<std::size_t>(t)][p];
    double* out = T.patches[p].u.data();
    for (const Recipe& r : recipes) {
      double v = 0;
      for (std::size_t m = r.begin; m < r.end; ++m) {
        const StoredTerm& x = terms[m];
        const double w = par[x.mask] * x.w;
        if (x.kind == Term::stored) v += w * fill_arrays[static_cast<std::size_t>(x.tier)][static_cast<std::size_t>(x.patch)][x.p];
        else v += w * (x.kind == Term::far ? eq.far_value : eq.dirichlet(R.points[static_cast<std::size_t>(x.p)]));
      }
      out[r.target] = v;
    }
    ghosts_filled += static_cast<long long>(recipes.size());
  };
  if (mine_only && nranks > 1) {
    const auto [u0, u1] = mine(*mine_only);
    for (std::size_t n = u0; n < u1; ++n)
      for (const int p : mine_only->units[n]) fill_patch(static_cast<std::size_t>(p));
    return;
  }
  for (std::size_t p = 0; p < T.patches.size(); ++p) fill_patch(p);
}

const Tier::Split& CompositeMultigrid::Impl::own_parents(int t) {
  Tier::Split& S = parents_of_own[static_cast<std::size_t>(t)];
  if (!S.first.empty()) return S;
  std::vector<int> parents;
  const auto [p0, p1] = own_patches(t);
  for (std::size_t p = p0; p < p1; ++p)
    parents.push_back(static_cast<int>(footprint(tiers[static_cast<std::size_t>(t)], tiers[static_cast<std::size_t>(t) - 1], p).parent));
  std::sort(parents.begin(), parents.end());
  parents.erase(std::unique(parents.begin(), parents.end()), parents.end());
  S = only_these(parents);
  return S;
}

Tier::Split CompositeMultigrid::Impl::only_these(const std::vector<int>& patches) const {
  Tier::Split S;
  for (const int p : patches) S.units.push_back({p});
  S.first.assign(static_cast<std::size_t>(nranks) + 1, S.units.size());
  for (int r = 0; r <= rank; ++r) S.first[static_cast<std::size_t>(r)] = 0;
  return S;
}

void CompositeMultigrid::Impl::relax(int t, const ScalarEquation& eq, const std::array<double, 64>& par, int sweeps) {
  Tier& T = tiers[static_cast<std::size_t>(t)];
  if (T.shape.dimension == 2 || curvilinear_3d()) return relax_lines(t, eq, par, sweeps);
  const auto [u0, u1] = mine(T.points);
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int colour = 0; colour < 2; ++colour) {
      fill(t, eq, par, &T.points);
      for (std::size_t u = u0; u < u1; ++u) {
        Level& P = T.patches[static_cast<std::size_t>(T.points.units[u][0])];
        count(t, red_black_pass(P, full_range(P), colour));
      }
      exchange(T, T.points, colour);  // the pass changed only this colour's cells
    }
}

void CompositeMultigrid::Impl::relax_lines(int t, const ScalarEquation& eq, const std::array<double, 64>& par, int sweeps) {
  Tier& T = tiers[static_cast<std::size_t>(t)];
  const int dims = T.shape.dimension;
  for (auto& runs : T.runs)
    for (auto& R : runs) copy_unit<true>(T, R, &Level::f, false);
  for (auto& R : T.shell) copy_unit<true>(T, R, &Level::f, false);
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int d = 0; d < dims; ++d) {
      const auto& S = T.lines[static_cast<std::size_t>(d)];
      fill(t, eq, par, &S);
      const auto [u0, u1] = mine(S);
      for (std::size_t u = u0; u < u1; ++u) {
        auto& R = T.runs[static_cast<std::size_t>(d)][u];
        copy_unit<true>(T, R, &Level::u, true);
        for (int colour = 0; colour < 2; ++colour) {
          if (dims == 2) {
            const Lines ln(R.level, d);
            count(t, line_pass(R.level, ln, colour, 0, ln.count));
          } else {
            count(t, line_pass_3d(R.level, eq, d, colour));
          }
        }
        copy_unit<false>(T, R, &Level::u, false);
      }
      exchange(T, S);
    }
  for (auto& R : T.shell) {
    fill(t, eq, par);
    copy_unit<true>(T, R, &Level::u, true);
    count(t, relax_inner_shells(R.level, eq, angular_shells(R.level)));
    copy_unit<false>(T, R, &Level::u, false);
  }
}

void CompositeMultigrid::Impl::vcycle(const ScalarEquation& eq, const std::array<double, 64>& par, const SolveSettings& s) {
  const int L = static_cast<int>(tiers.size()) - 1;
  for (int t = L; t >= 1; --t) {
    relax(t, eq, par, s.pre_sweeps);
    Tier& C = tiers[static_cast<std::size_t>(t - 1)];
    // The solution and the residual restricted into r and u of the coarse patches' covered cells.
    restrict_own_patches(t, eq, par, true);
    // The coarse right-hand side in the covered cells, A(R u) + R r: each rank for the footprints of
    // its own fine patches (the rows through them), then exchanged like the restriction. Only the
    // ghosts of those footprints' parents are read.
    if (t - 1 >= 1) fill(t - 1, eq, par, &own_parents(t));
    else fill(0, eq, par);
    const auto [p0, p1] = own_patches(t);
    for (std::size_t p = p0; p < p1; ++p) {
      const Footprint fp = footprint(tiers[static_cast<std::size_t>(t)], C, p);
      Level& Q = C.patches[fp.parent];
      std::vector<double>& Au = C.scratch[fp.parent];
      Au.resize(Q.cells());
      apply_operator(Q, Q.u, Au, {fp.lo[1], fp.lo[1] + fp.n[1], fp.lo[2], fp.lo[2] + fp.n[2]});
      for (int k = fp.lo[2]; k < fp.lo[2] + fp.n[2]; ++k)
        for (int j = fp.lo[1]; j < fp.lo[1] + fp.n[1]; ++j)
          for (int i = fp.lo[0]; i < fp.lo[0] + fp.n[0]; ++i) {
            const std::size_t q = Q.cell(i, j, k);
            Q.f[q] = Au[q] + Q.r[q];
          }
    }
    exchange_footprint_values(t, 1, [&](std::size_t parent, int i, int j, int k, auto&& value) {
      Level& Q = C.patches[parent];
      value(Q.f[Q.cell(i, j, k)]);
    });
    for (std::size_t p = 0; p < C.patches.size(); ++p) C.ubar[p] = C.patches[p].u;
  }
  // Base V-cycle.
  Level& B = tiers[0].patches[0];
  base_u.resize(B.cells());
  for_cells(B, full_range(B), [&](std::size_t q, std::ptrdiff_t p) { base_u[q] = B.u[static_cast<std::size_t>(p)]; });
  base.cycle(base_eq, base_u, B.f, s);
  for_cells(B, full_range(B), [&](std::size_t q, std::ptrdiff_t p) { B.u[static_cast<std::size_t>(p)] = base_u[q]; });
  for (int t = 1; t <= L; ++t) {
    Tier& C = tiers[static_cast<std::size_t>(t - 1)];
    for (std::size_t p = 0; p < C.patches.size(); ++p) {
      const std::vector<double>& u = C.patches[p].u;
      C.corr[p].resize(u.size());
      for (std::size_t m = 0; m < u.size(); ++m) C.corr[p][m] = u[m] - C.ubar[p][m];
    }
    // Each rank corrects its own patches; the interiors are exchanged before the relaxation (whose
    // ghosts read other ranks' patches).
    Tier& T = tiers[static_cast<std::size_t>(t)];
    const auto [p0, p1] = own_patches(t);
    interpolate_up(t, eq, par, true, [&](int tier, int patch) -> const std::vector<double>& {
      return tiers[static_cast<std::size_t>(tier)].corr[static_cast<std::size_t>(patch)];
    }, p0, p1);
    exchange(T, T.points);
    relax(t, eq, par, s.post_sweeps);
  }
}

// Each rank evaluates the residual of its share of the leaf cells only (the base level's planes along
// its last used direction, and its patches of each tier's point split) and the maxima are reduced:
// a max is exact in any order, so the bits of the result do not depend on the number of ranks. The
// residuals of the other ranks' cells are left stale: the V-cycle recomputes every residual it reads.
CompositeMultigrid::Impl::LeafResidual CompositeMultigrid::Impl::leaf_residual(const ScalarEquation& eq, const std::array<double, 64>& par) {
  double m[3] = {0, 0, 0};  // max |r|, max of the source terms, max of |r| above each cell's floor
  constexpr double ulps = 256 * std::numeric_limits<double>::epsilon();
  auto account = [&](const Level& P, const std::vector<char>& covered, const Range& R) {
    const Ops o(P);
    for_cells(P, R, [&](std::size_t q, std::ptrdiff_t g) {
      if (covered[q]) return;
      const double u = P.u[static_cast<std::size_t>(g)];
      double sc = std::abs(o.k[q] * u) + std::abs(o.s0[q]);
      if (o.s1) sc += std::abs(o.s1[q] / u);
      if (o.s7) sc += std::abs(o.s7[q] / std::pow(u, 7));
      m[0] = std::max(m[0], std::abs(P.r[q]));
      m[2] = std::max(m[2], std::abs(P.r[q]) - ulps * P.diagonal[q] * std::abs(u));
      m[1] = std::max(m[1], sc);
    });
  };
  for (int t = 0; t < static_cast<int>(tiers.size()); ++t) {
    Tier& T = tiers[static_cast<std::size_t>(t)];
    if (t == 0) {
      Level& B = T.patches[0];
      fill(0, eq, par);
      const Range R = base_share(B);
      apply_operator(B, B.u, B.r, R);
      for_cells(B, R, [&](std::size_t q, std::ptrdiff_t) { B.r[q] = -B.r[q]; });
      account(B, T.covered[0], R);
      continue;
    }
    for (auto& P : T.patches) std::fill(P.f.begin(), P.f.end(), 0.0);
    fill(t, eq, par, &T.points);  // the ghosts of this rank's patches
    const auto [u0, u1] = mine(T.points);
    for (std::size_t n = u0; n < u1; ++n) {
      const auto p = static_cast<std::size_t>(T.points.units[n][0]);
      Level& P = T.patches[p];
      apply_operator(P, P.u, P.r, full_range(P));
      for (std::size_t q = 0; q < P.cells(); ++q) P.r[q] = P.f[q] - P.r[q];
      account(P, T.covered[p], full_range(P));
    }
  }
  if (nranks > 1) {
    MPI_Allreduce(MPI_IN_PLACE, m, 3, MPI_DOUBLE, MPI_MAX, comm);
    comm::count("mg_residual_allreduce", comm::Pattern::allreduce, -1, 1, 3 * sizeof(double));
  }
  return {m[0], m[1], m[2]};
}

Range CompositeMultigrid::Impl::base_share(const Level& B) const {
  Range R = full_range(B);
  if (nranks == 1) return R;
  // Planes along the last used direction (i is never split: Range holds whole rows).
  const int d = B.shape.dimension;
  if (d < 2) return R;
  int& lo = d == 3 ? R.k0 : R.j0;
  int& hi = d == 3 ? R.k1 : R.j1;
  const int n = hi;
  lo = n * rank / nranks;
  hi = n * (rank + 1) / nranks;
  return R;
}

void CompositeMultigrid::Impl::restrict_solution(const ScalarEquation& eq, const std::array<double, 64>& par) {
  for (int t = static_cast<int>(tiers.size()) - 1; t >= 1; --t) restrict_own_patches(t, eq, par, false);
}

void CompositeMultigrid::Impl::restrict_own_patches(int t, const ScalarEquation& eq, const std::array<double, 64>& par,
                                                     bool with_residual) {
  Tier &T = tiers[static_cast<std::size_t>(t)], &C = tiers[static_cast<std::size_t>(t - 1)];
  const auto [p0, p1] = own_patches(t);
  fill(t, eq, par, &T.points);  // restrict_point_values reads the fine ghosts
  if (with_residual)
    for (std::size_t p = p0; p < p1; ++p) {
      Level& P = T.patches[p];
      apply_operator(P, P.u, P.r, full_range(P));
      for (std::size_t q = 0; q < P.cells(); ++q) P.r[q] = P.f[q] - P.r[q];
    }
  restrict_point_values(t, p0, p1);
  if (with_residual)
    restrict_tier(t, [&](std::size_t p, std::size_t q) { return T.patches[p].r[q]; },
                  [&](std::size_t p, std::size_t q) -> double& { return C.patches[p].r[q]; }, p0, p1);
  exchange_footprints(t, with_residual);
}

void CompositeMultigrid::Impl::exchange_footprints(int t, bool with_residual) {
  Tier& C = tiers[static_cast<std::size_t>(t - 1)];
  exchange_footprint_values(t, with_residual ? 2 : 1, [&](std::size_t parent, int i, int j, int k, auto&& value) {
    Level& Q = C.patches[parent];
    value(Q.u[static_cast<std::size_t>(Q.at(i, j, k))]);
    if (with_residual) value(Q.r[Q.cell(i, j, k)]);
  });
}

}  // namespace remnant::xcfc
