// Composite FAS multigrid on refined patches (see include/XCFC/composite_multigrid.hpp). Each level
// ("tier") is a set of patches, each patch a Level with one ghost layer; tier 0 is the base grid as
// one patch, solved by Multigrid. Ghost values and the coarse windows of the prolongation are affine
// "recipes" in stored interior values, built once per boundary signature by resolving symmetry
// mirrors, outer boundaries and coarse-fine interpolation symbolically.
#include "XCFC/composite_multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "boundary_ghosts.hpp"
#include "composite_layout.hpp"
#include "composite_recipes.hpp"
#include "composite_tier.hpp"
#include "composite_transfers.hpp"
#include "level.hpp"
#include "level_ops.hpp"
#include "line_relaxation.hpp"
#include "line_relaxation_3d.hpp"
#include "point_relaxation.hpp"
#include "shell_relaxation.hpp"

namespace remnant::xcfc {

struct CompositeMultigrid::Impl {
  CompositeLayout layout;
  std::vector<Tier> tiers;
  Multigrid base;
  std::map<std::pair<double, bool>, Recipes> recipes;
  ScalarEquation base_eq;  // boundary data plus the base coefficients (fine ones restricted)
  std::vector<double> base_u, base_f;
  std::vector<std::pair<int, int>> part_of;  // (tier, patch) of each part
  std::vector<PartGeometry> geometry;

  MPI_Comm comm;
  int rank = 0, nranks = 1;
  long long relaxed_finest = 0, relaxed_all = 0;  // cells relaxed by this rank in the current solve
  void count(int t, long long n) {
    relaxed_all += n;
    if (t + 1 == static_cast<int>(tiers.size())) relaxed_finest += n;
  }

  Impl(const CompositeLayout& l, MPI_Comm c) : layout(l), base(l.base, c), comm(c) {
    if (comm != MPI_COMM_SELF) {  // MPI_COMM_SELF needs no MPI call (unit tests, benchmarks without MPI_Init)
      MPI_Comm_rank(comm, &rank);
      MPI_Comm_size(comm, &nranks);
    }
    tiers = build_tiers(l, nranks);
    const int L = l.finest();
    for (int t = 0; t <= L; ++t)
      for (std::size_t p = 0; p < tiers[static_cast<std::size_t>(t)].patches.size(); ++p) {
        part_of.emplace_back(t, static_cast<int>(p));
        const Level& P = tiers[static_cast<std::size_t>(t)].patches[p];
        PartGeometry g;
        g.shape = P.shape, g.level = t, g.strides = P.st, g.ghosts = P.g;
        if (t == 0) {
          g.shared = &base.frames();
        } else {
          g.own.J.assign(P.ghosted_size, Matrix3{});
          g.own.f.assign(P.ghosted_size, Point3{1, 1, 1});
          for (int k = -P.g[2]; k < P.shape.n[2] + P.g[2]; ++k)
            for (int j = -P.g[1]; j < P.shape.n[1] + P.g[1]; ++j)
              for (int i = -P.g[0]; i < P.shape.n[0] + P.g[0]; ++i) {
                const Point3 x = P.shape.point(i, j, k);
                const auto q = static_cast<std::size_t>(P.at(i, j, k));
                g.own.J[q] = coords::jacobian(P.shape.coordinates, x);
                g.own.f[q] = coords::metric_diagonal(P.shape.coordinates, x);
              }
        }
        geometry.push_back(std::move(g));
      }
  }
  std::size_t part_index(int t, std::size_t p) const {
    std::size_t i = p;
    for (int s = 0; s < t; ++s) i += tiers[static_cast<std::size_t>(s)].patches.size();
    return i;
  }
  bool refined() const { return tiers.size() > 1; }
  // 3D cylindrical and spherical: patches relax along runs in all three directions (cyclic around
  // whole phi rings) and the origin's complete shells as planes, as the base level does.
  bool curvilinear_3d() const { return layout.base.dimension == 3 && layout.base.coordinates != CoordinateSystem::cartesian; }

  Tier::Split split(const Tier& T, std::vector<std::vector<int>> units) const { return make_split(T, std::move(units), nranks); }
  std::pair<std::size_t, std::size_t> mine(const Tier::Split& S) const { return owned_units(S, rank); }
  void exchange(Tier& T, const Tier::Split& S) { exchange_units(T, S, comm, rank, nranks); }

  int locate(int t, const Cell& I) const { return xcfc::locate(tiers[static_cast<std::size_t>(t)], I); }

  std::size_t coarse_cell(int t, std::size_t p, int i, int j, int k) const {
    return xcfc::coarse_cell(tiers[static_cast<std::size_t>(t)], tiers[static_cast<std::size_t>(t - 1)], p, i, j, k);
  }
  bool used(int d) const { return layout.base.used(d); }

  // ---- recipes -----------------------------------------------------------------------------------
  // Appends the terms of the value at cell I of tier t (any cell within reach of the domain).
  void expand(int t, Cell I, double w, unsigned mask, double falloff, bool dirichlet, std::vector<Term>& out) const {
    const Tier& T = tiers[static_cast<std::size_t>(t)];
    const GridShape& s = T.shape;
    for (int d = 0; d < s.dimension; ++d) {
      if (I[d] >= 0 && I[d] < s.n[d]) continue;
      const int side = I[d] < 0 ? 0 : 1;
      const Boundary kind = s.boundary[d][side];
      if (kind == Boundary::outer) {
        Cell in = I;
        in[d] = side == 0 ? 0 : s.n[d] - 1;
        const Point3 xg = s.point(static_cast<int>(I[0]), static_cast<int>(I[1]), static_cast<int>(I[2]));
        if (dirichlet) {
          Term f;
          f.kind = Term::dirichlet, f.mask = static_cast<unsigned char>(mask), f.w = 2 * w, f.x = xg;
          f.x[d] = s.face(d, side == 0 ? 0 : s.n[d]);
          out.push_back(f);
          return expand(t, in, -w, mask, falloff, dirichlet, out);
        }
        const Point3 Xi = coords::to_cartesian(s.coordinates, s.point(static_cast<int>(in[0]), static_cast<int>(in[1]), static_cast<int>(in[2])));
        const Point3 Xg = coords::to_cartesian(s.coordinates, xg);
        const double rho = std::pow(std::hypot(Xi[0], Xi[1], Xi[2]) / std::hypot(Xg[0], Xg[1], Xg[2]), falloff);
        Term f;
        f.kind = Term::far, f.mask = static_cast<unsigned char>(mask), f.w = w * (1 - rho);
        out.push_back(f);
        return expand(t, in, w * rho, mask, falloff, dirichlet, out);
      }
      // Periodic images keep the parity mask (their parity is +1 for every field anyway).
      const unsigned crossed = kind == Boundary::periodic ? 0u : 1u << (2 * d + side);
      return expand(t, s.image(I, d, side), w, mask ^ crossed, falloff, dirichlet, out);
    }
    const int p = locate(t, I);
    if (p >= 0) {
      const Cell& c = T.corner[static_cast<std::size_t>(p)];
      Term v;
      v.mask = static_cast<unsigned char>(mask), v.tier = t, v.patch = p, v.w = w;
      v.p = T.patches[static_cast<std::size_t>(p)].at(static_cast<int>(I[0] - c[0]), static_cast<int>(I[1] - c[1]),
                                                      static_cast<int>(I[2] - c[2]));
      out.push_back(v);
      return;
    }
    if (t == 0) throw std::logic_error("CompositeMultigrid: base cell not found");
    // Not on this level: tensor-product quadratic interpolation of the coarser level.
    std::array<std::array<double, 3>, 3> wq{};
    Cell C{};
    for (int d = 0; d < 3; ++d) {
      wq[d] = {0, 1, 0};
      C[d] = I[d];
      if (!s.used(d)) continue;
      C[d] = I[d] >= 0 ? I[d] / 2 : -((1 - I[d]) / 2);
      wq[d] = quadratic((I[d] - 2 * C[d]) == 1 ? 0.25 : -0.25);
    }
    for (int c = 0; c < 3; ++c)
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
          const double weight = wq[0][a] * wq[1][b] * wq[2][c];
          if (weight == 0) continue;
          expand(t - 1, {C[0] + a - 1, C[1] + b - 1, C[2] + c - 1}, w * weight, mask, falloff, dirichlet, out);
        }
  }

  const Recipes& recipes_for(const ScalarEquation& eq) {
    const std::pair<double, bool> sig{eq.dirichlet ? 0.0 : eq.falloff, static_cast<bool>(eq.dirichlet)};
    auto it = recipes.find(sig);
    if (it != recipes.end()) return it->second;
    Recipes& R = recipes[sig];
    R.ghosts.resize(tiers.size());
    R.window.resize(tiers.size());
    std::vector<Term> terms;
    for (int t = 1; t < static_cast<int>(tiers.size()); ++t) {
      const Tier& T = tiers[static_cast<std::size_t>(t)];
      R.ghosts[static_cast<std::size_t>(t)].resize(T.patches.size());
      R.window[static_cast<std::size_t>(t)].resize(T.patches.size());
      for (std::size_t p = 0; p < T.patches.size(); ++p) {
        const Level& P = T.patches[p];
        const Cell& c = T.corner[p];
        auto& gl = R.ghosts[static_cast<std::size_t>(t)][p];
        for (int d = 0; d < 3; ++d) {
          if (!used(d)) continue;
          const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
          for (int side = 0; side < 2; ++side)
            for (int t2 = 0; t2 < P.shape.n[e2]; ++t2)
              for (int t1 = 0; t1 < P.shape.n[e1]; ++t1) {
                std::array<int, 3> g{};
                g[d] = side == 0 ? -1 : P.shape.n[d], g[e1] = t1, g[e2] = t2;
                expand(t, {c[0] + g[0], c[1] + g[1], c[2] + g[2]}, 1.0, 0, sig.first, sig.second, terms);
                add_recipe(R, gl, static_cast<std::size_t>(P.at(g[0], g[1], g[2])), terms);
              }
        }
        auto& wl = R.window[static_cast<std::size_t>(t)][p];
        const auto& wn = T.window_n[p];
        std::size_t w = 0;
        for (int k = 0; k < wn[2]; ++k)
          for (int j = 0; j < wn[1]; ++j)
            for (int i = 0; i < wn[0]; ++i, ++w) {
              const std::array<int, 3> a{i, j, k};
              Cell I{};
              for (int d = 0; d < 3; ++d) I[d] = used(d) ? c[d] / 2 + a[d] - 1 : 0;
              expand(t - 1, I, 1.0, 0, sig.first, sig.second, terms);
              add_recipe(R, wl, w, terms);
            }
      }
    }
    return R;
  }

  // ---- equation set-up --------------------------------------------------------------------------
  static void add_mode_term(Level& L, AngularMode mode) {
    L.k = L.k_eq;
    if (mode == AngularMode::none) return;
    const auto& mk = L.mode_k[static_cast<int>(mode)];
    for (std::size_t q = 0; q < L.k.size(); ++q) L.k[q] += mk[q];
  }

  template <class Fine, class Coarse>
  void restrict_tier(int t, Fine&& fine, Coarse&& coarse) const {
    xcfc::restrict_tier(tiers[static_cast<std::size_t>(t)], tiers[static_cast<std::size_t>(t - 1)], fine, coarse);
  }
  void restrict_point_values(int t) {
    xcfc::restrict_point_values(tiers[static_cast<std::size_t>(t)], tiers[static_cast<std::size_t>(t - 1)]);
  }

  void set_equation(const CompositeEquation& eq) {
    auto take = [&](const CompositeField& f, int t, std::size_t p, std::size_t n, std::vector<double>& out, bool optional) {
      const std::vector<double>* src = f.empty() ? nullptr : &f.part.at(part_index(t, p));
      if (!src) {
        if (optional) out.clear();
        else out.assign(n, 0.0);
      } else {
        if (src->size() != n) throw std::invalid_argument("CompositeMultigrid: a coefficient array has the wrong size");
        out.assign(src->begin(), src->end());
      }
    };
    for (int t = 0; t < static_cast<int>(tiers.size()); ++t)
      for (std::size_t p = 0; p < tiers[static_cast<std::size_t>(t)].patches.size(); ++p) {
        Level& P = tiers[static_cast<std::size_t>(t)].patches[p];
        take(eq.k, t, p, P.cells(), P.k_eq, false);
        take(eq.s0, t, p, P.cells(), P.s0, false);
        take(eq.s1, t, p, P.cells(), P.s1, true);
        take(eq.s7, t, p, P.cells(), P.s7, true);
      }
    // Covered cells take the restriction of the finer coefficients (finest first).
    for (int t = static_cast<int>(tiers.size()) - 1; t >= 1; --t) {
      auto& T = tiers[static_cast<std::size_t>(t)];
      auto& C = tiers[static_cast<std::size_t>(t - 1)];
      auto pass = [&](std::vector<double> Level::*a) {
        if ((T.patches[0].*a).empty()) return;
        restrict_tier(t, [&](std::size_t p, std::size_t q) { return (T.patches[p].*a)[q]; },
                      [&](std::size_t p, std::size_t q) -> double& { return (C.patches[p].*a)[q]; });
      };
      pass(&Level::k_eq), pass(&Level::s0), pass(&Level::s1), pass(&Level::s7);
    }
    for (auto& T : tiers)
      for (auto& P : T.patches) {
        add_mode_term(P, eq.boundary.mode);
        P.f.assign(P.cells(), 0.0);
        P.r.assign(P.cells(), 0.0);
        if (P.u.size() != P.ghosted_size) P.u.assign(P.ghosted_size, 0.0);
        set_line_ends(P, eq.boundary);
        factor_lines(P);
      }
    // Runs (and 3D shells): the equation copied from their patches, line ends and factors.
    for (auto& T : tiers) {
      auto prepare_unit = [&](Tier::Run& R) {
        Level& RL = R.level;
        const Level& P0 = T.patches[static_cast<std::size_t>(R.patches.front())];
        for (auto a : {&Level::k_eq, &Level::s0, &Level::s1, &Level::s7}) {
          if ((P0.*a).empty()) {
            (RL.*a).clear();
            continue;
          }
          (RL.*a).assign(RL.cells(), 0.0);
          copy_unit<true>(T, R, a, false);
        }
        add_mode_term(RL, eq.boundary.mode);
        RL.f.assign(RL.cells(), 0.0);
        RL.r.assign(RL.cells(), 0.0);
        RL.u.assign(RL.ghosted_size, 0.0);
        if (curvilinear_3d()) return factor_lines_3d(RL, eq.boundary);
        set_line_ends(RL, eq.boundary);
        factor_lines(RL);
      };
      for (auto& runs : T.runs)
        for (auto& R : runs) prepare_unit(R);
      for (auto& R : T.shell) prepare_unit(R);
    }
    base_eq = eq.boundary;
    const Level& B = tiers[0].patches[0];
    base_eq.k = B.k_eq, base_eq.s0 = B.s0, base_eq.s1 = B.s1, base_eq.s7 = B.s7;
    base.prepare(base_eq);
  }

  // ---- operations on a tier ---------------------------------------------------------------------
  void fill(int t, const ScalarEquation& eq, const std::array<double, 64>& par) {
    Tier& T = tiers[static_cast<std::size_t>(t)];
    if (t == 0) return fill_ghosts(T.patches[0], eq, T.patches[0].u, false);
    const Recipes& R = recipes_for(eq);
    auto u = [&](int tier, int patch) -> const std::vector<double>& {
      return tiers[static_cast<std::size_t>(tier)].patches[static_cast<std::size_t>(patch)].u;
    };
    for (std::size_t p = 0; p < T.patches.size(); ++p)
      for (const Recipe& r : R.ghosts[static_cast<std::size_t>(t)][p])
        T.patches[p].u[r.target] = evaluate(R, r, par, eq, false, u);
  }

  // Relaxation of a tier's patches: red-black points (1D, 3D Cartesian) or zebra lines along runs of
  // patches in every direction (2D, 3D cylindrical and spherical; a row split into patches is one
  // line), ghosts refilled before each pass and held during it, both colours of a pass solved on
  // the run's copy. Each rank relaxes its units (patches or runs) and the results are exchanged: a
  // unit reads only ghosts and its own cells, so the bits do not depend on the number of ranks.
  // (Exact line solves of whole 1D patches with held ends would leave kinks at the patch ends that
  // the coarse correction removes slowly: points converge at 0.1-0.2 per cycle instead.)
  void relax(int t, const ScalarEquation& eq, const std::array<double, 64>& par, int sweeps) {
    Tier& T = tiers[static_cast<std::size_t>(t)];
    if (T.shape.dimension == 2 || curvilinear_3d()) return relax_lines(t, eq, par, sweeps);
    const auto [u0, u1] = mine(T.points);
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int colour = 0; colour < 2; ++colour) {
        fill(t, eq, par);
        for (std::size_t u = u0; u < u1; ++u) {
          Level& P = T.patches[static_cast<std::size_t>(T.points.units[u][0])];
          count(t, red_black_pass(P, full_range(P), colour));
        }
        exchange(T, T.points);
      }
  }

  // Zebra lines along the runs of each direction, then (3D spherical) the origin's complete shells
  // as planes; every rank does the shells (they are few, and the tier is complete on every rank
  // after the line passes).
  void relax_lines(int t, const ScalarEquation& eq, const std::array<double, 64>& par, int sweeps) {
    Tier& T = tiers[static_cast<std::size_t>(t)];
    const int dims = T.shape.dimension;
    for (auto& runs : T.runs)
      for (auto& R : runs) copy_unit<true>(T, R, &Level::f, false);
    for (auto& R : T.shell) copy_unit<true>(T, R, &Level::f, false);
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int d = 0; d < dims; ++d) {
        fill(t, eq, par);
        const auto& S = T.lines[static_cast<std::size_t>(d)];
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

  // r = f - A(u) on every patch of the tier (ghosts filled first).
  void residual(int t, const ScalarEquation& eq, const std::array<double, 64>& par) {
    fill(t, eq, par);
    for (auto& P : tiers[static_cast<std::size_t>(t)].patches) {
      apply_operator(P, P.u, P.r, full_range(P));
      for (std::size_t q = 0; q < P.cells(); ++q) P.r[q] = P.f[q] - P.r[q];
    }
  }

  // Interpolates (quadratic, from the coarse window) `source` of tier t - 1 into the patches of
  // tier t: added to u (a correction) or replacing it.
  template <class Field>
  void interpolate_up(int t, const ScalarEquation& eq, const std::array<double, 64>& par, bool correction, Field&& source) {
    Tier& T = tiers[static_cast<std::size_t>(t)];
    const Recipes& R = recipes_for(eq);
    std::vector<double> win;
    for (std::size_t p = 0; p < T.patches.size(); ++p) {
      Level& P = T.patches[p];
      win.assign(T.window_size[p], 0.0);
      for (const Recipe& r : R.window[static_cast<std::size_t>(t)][p]) win[r.target] = evaluate(R, r, par, eq, correction, source);
      const auto& wn = T.window_n[p];
      for (int k = 0; k < P.shape.n[2]; ++k)
        for (int j = 0; j < P.shape.n[1]; ++j)
          for (int i = 0; i < P.shape.n[0]; ++i) {
            const std::array<int, 3> f{i, j, k};
            std::array<std::array<double, 3>, 3> wq{};
            std::array<int, 3> c{}, lo{}, hi{};
            for (int d = 0; d < 3; ++d) {
              if (used(d)) c[d] = f[d] / 2 + 1, wq[d] = quadratic((f[d] & 1) ? 0.25 : -0.25), lo[d] = 0, hi[d] = 3;
              else c[d] = 0, wq[d] = {0, 1, 0}, lo[d] = 1, hi[d] = 2;
            }
            double v = 0;
            for (int z = lo[2]; z < hi[2]; ++z)
              for (int y = lo[1]; y < hi[1]; ++y)
                for (int x = lo[0]; x < hi[0]; ++x)
                  v += wq[0][x] * wq[1][y] * wq[2][z] *
                       win[static_cast<std::size_t>((c[0] + x - 1) + wn[0] * ((c[1] + y - 1) + wn[1] * (c[2] + z - 1)))];
            double& u = P.u[static_cast<std::size_t>(P.at(i, j, k))];
            u = correction ? u + v : v;
          }
    }
  }

  // ---- the composite V-cycle --------------------------------------------------------------------
  void vcycle(const ScalarEquation& eq, const std::array<double, 64>& par, const SolveSettings& s) {
    const int L = static_cast<int>(tiers.size()) - 1;
    for (int t = L; t >= 1; --t) {
      relax(t, eq, par, s.pre_sweeps);
      residual(t, eq, par);
      Tier &T = tiers[static_cast<std::size_t>(t)], &C = tiers[static_cast<std::size_t>(t - 1)];
      restrict_point_values(t);  // ghosts filled by residual()
      // The restricted residual, kept in r of the coarse patches' covered cells.
      restrict_tier(t, [&](std::size_t p, std::size_t q) { return T.patches[p].r[q]; },
                    [&](std::size_t p, std::size_t q) -> double& { return C.patches[p].r[q]; });
      fill(t - 1, eq, par);
      for (std::size_t p = 0; p < C.patches.size(); ++p) {
        Level& Q = C.patches[p];
        std::vector<double>& Au = C.scratch[p];
        Au.resize(Q.cells());
        apply_operator(Q, Q.u, Au, full_range(Q));
        const auto& cov = C.covered[p];
        for (std::size_t q = 0; q < Q.cells(); ++q)
          if (cov[q]) Q.f[q] = Au[q] + Q.r[q];
        C.ubar[p] = Q.u;
      }
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
      interpolate_up(t, eq, par, true, [&](int tier, int patch) -> const std::vector<double>& {
        return tiers[static_cast<std::size_t>(tier)].corr[static_cast<std::size_t>(patch)];
      });
      relax(t, eq, par, s.post_sweeps);
    }
  }

  // Max |r| and max source scale over the leaf cells.
  // Over the leaf cells: max |r|, max of the source terms, and max of |r| less each cell's round-off
  // floor (256 ulp of its largest operator term: next to the spherical origin the coefficients are
  // large, and one global floor from the largest of them would stop the solve early elsewhere).
  struct LeafResidual {
    double max = 0, scale = 0, above_floor = 0;
  };
  LeafResidual leaf_residual(const ScalarEquation& eq, const std::array<double, 64>& par) {
    double rmax = 0, smax = 0, excess = 0;
    constexpr double ulps = 256 * std::numeric_limits<double>::epsilon();
    for (int t = 0; t < static_cast<int>(tiers.size()); ++t) {
      Tier& T = tiers[static_cast<std::size_t>(t)];
      if (t == 0) {
        Level& B = T.patches[0];
        fill(0, eq, par);
        apply_operator(B, B.u, B.r, full_range(B));
        for (std::size_t q = 0; q < B.cells(); ++q) B.r[q] = -B.r[q];
      } else {
        for (auto& P : T.patches) std::fill(P.f.begin(), P.f.end(), 0.0);
        residual(t, eq, par);
      }
      for (std::size_t p = 0; p < T.patches.size(); ++p) {
        const Level& P = T.patches[p];
        const Ops o(P);
        for_cells(P, full_range(P), [&](std::size_t q, std::ptrdiff_t g) {
          if (T.covered[p][q]) return;
          const double u = P.u[static_cast<std::size_t>(g)];
          double sc = std::abs(o.k[q] * u) + std::abs(o.s0[q]);
          if (o.s1) sc += std::abs(o.s1[q] / u);
          if (o.s7) sc += std::abs(o.s7[q] / std::pow(u, 7));
          rmax = std::max(rmax, std::abs(P.r[q]));
          excess = std::max(excess, std::abs(P.r[q]) - ulps * P.diagonal[q] * std::abs(u));
          smax = std::max(smax, sc);
        });
      }
    }
    return {rmax, smax, excess};
  }

  void load(const CompositeField& u, bool nonlinear) {
    for (std::size_t i = 0; i < part_of.size(); ++i) {
      Level& P = tiers[static_cast<std::size_t>(part_of[i].first)].patches[static_cast<std::size_t>(part_of[i].second)];
      P.u.assign(P.ghosted_size, nonlinear ? 1.0 : 0.0);
      if (i < u.part.size() && u.part[i].size() == P.cells())
        for_cells(P, full_range(P), [&](std::size_t q, std::ptrdiff_t g) { P.u[static_cast<std::size_t>(g)] = u.part[i][q]; });
    }
  }
  void store(CompositeField& u) const {
    u.part.resize(part_of.size());
    for (std::size_t i = 0; i < part_of.size(); ++i) {
      const Level& P = tiers[static_cast<std::size_t>(part_of[i].first)].patches[static_cast<std::size_t>(part_of[i].second)];
      u.part[i].resize(P.cells());
      for_cells(P, full_range(P), [&](std::size_t q, std::ptrdiff_t g) { u.part[i][q] = P.u[static_cast<std::size_t>(g)]; });
    }
  }
  ScalarEquation base_equation(const CompositeEquation& eq) const {
    ScalarEquation b = eq.boundary;
    if (!eq.k.empty()) b.k = eq.k.part[0];
    if (!eq.s0.empty()) b.s0 = eq.s0.part[0];
    if (!eq.s1.empty()) b.s1 = eq.s1.part[0];
    if (!eq.s7.empty()) b.s7 = eq.s7.part[0];
    return b;
  }

  // Covered cells hold the restriction of the finer solution (finest first).
  void restrict_solution(const ScalarEquation& eq, const std::array<double, 64>& par) {
    for (int t = static_cast<int>(tiers.size()) - 1; t >= 1; --t) {
      fill(t, eq, par);
      restrict_point_values(t);
    }
  }
};

CompositeMultigrid::CompositeMultigrid(const CompositeLayout& layout, MPI_Comm comm)
    : impl_(std::make_unique<Impl>(layout, comm)) {}
CompositeMultigrid::CompositeMultigrid(const GridShape& shape, MPI_Comm comm)
    : CompositeMultigrid(CompositeLayout{shape, {1, 1, 1}, {}}, comm) {}
CompositeMultigrid::~CompositeMultigrid() = default;
CompositeMultigrid::CompositeMultigrid(CompositeMultigrid&&) noexcept = default;
CompositeMultigrid& CompositeMultigrid::operator=(CompositeMultigrid&&) noexcept = default;

const CompositeLayout& CompositeMultigrid::layout() const { return impl_->layout; }
Multigrid& CompositeMultigrid::base() { return impl_->base; }
int CompositeMultigrid::parts() const { return static_cast<int>(impl_->part_of.size()); }
const PartGeometry& CompositeMultigrid::part(int i) const { return impl_->geometry.at(static_cast<std::size_t>(i)); }
bool CompositeMultigrid::covered(int i, std::size_t q) const {
  const auto [t, p] = impl_->part_of.at(static_cast<std::size_t>(i));
  return impl_->tiers[static_cast<std::size_t>(t)].covered[static_cast<std::size_t>(p)].at(q) != 0;
}
CompositeField CompositeMultigrid::field(double value) const {
  CompositeField f;
  for (const auto& g : impl_->geometry) f.part.emplace_back(g.shape.cells(), value);
  return f;
}

void CompositeMultigrid::fill_covered(CompositeField& f) const {
  const Impl& m = *impl_;
  for (int t = static_cast<int>(m.tiers.size()) - 1; t >= 1; --t)
    m.restrict_tier(t, [&](std::size_t p, std::size_t q) { return f.part[m.part_index(t, p)][q]; },
                    [&](std::size_t p, std::size_t q) -> double& { return f.part[m.part_index(t - 1, p)][q]; });
}

CompositeField CompositeMultigrid::with_ghosts(const ScalarEquation& boundary, const CompositeField& u) {
  Impl& m = *impl_;
  if (!m.refined()) return {{m.base.with_ghosts(boundary, u.part.at(0))}};
  const auto par = parity_factors(boundary);
  m.load(u, false);
  m.restrict_solution(boundary, par);
  CompositeField out;
  for (int t = 0; t < static_cast<int>(m.tiers.size()); ++t) m.fill(t, boundary, par);
  for (const auto& [t, p] : m.part_of) out.part.push_back(m.tiers[static_cast<std::size_t>(t)].patches[static_cast<std::size_t>(p)].u);
  return out;
}

SolveStats CompositeMultigrid::solve(const CompositeEquation& eq, CompositeField& u, const SolveSettings& s) {
  Impl& m = *impl_;
  if (!m.refined()) {
    u.part.resize(1);
    return m.base.solve(m.base_equation(eq), u.part[0], s);
  }
  m.set_equation(eq);
  m.relaxed_finest = m.relaxed_all = 0;
  const ScalarEquation& bc = eq.boundary;
  const auto par = parity_factors(bc);
  SolveStats st;
  if (s.full_multigrid) {
    // Nested iteration: the base problem (fine coefficients restricted), then interpolated up.
    SolveSettings bs = s;
    bs.tolerance = std::max(s.tolerance, 1e-6);
    m.base_u.assign(m.tiers[0].patches[0].cells(), eq.nonlinear() ? 1.0 : 0.0);
    m.base.solve(m.base_eq, m.base_u, bs);
    CompositeField start;
    start.part.push_back(m.base_u);
    m.load(start, eq.nonlinear());
    m.base.prepare(m.base_eq);
    for (int t = 1; t < static_cast<int>(m.tiers.size()); ++t) {
      m.interpolate_up(t, bc, par, false, [&](int tier, int patch) -> const std::vector<double>& {
        return m.tiers[static_cast<std::size_t>(tier)].patches[static_cast<std::size_t>(patch)].u;
      });
    }
  } else {
    m.load(u, eq.nonlinear());
  }
  m.restrict_solution(bc, par);
  Impl::LeafResidual r = m.leaf_residual(bc, par);
  st.initial_residual = r.max;
  auto scale_of = [&](const Impl::LeafResidual& x) {
    const double sc = std::max(x.scale, s.scale_floor);
    return sc > 0 ? sc : 1.0;
  };
  st.scale = scale_of(r);
  while (r.above_floor > s.tolerance * st.scale && st.cycles < s.max_cycles) {
    m.vcycle(bc, par, s);
    m.restrict_solution(bc, par);
    ++st.cycles;
    r = m.leaf_residual(bc, par);
    st.scale = scale_of(r);
    st.history.push_back(r.max);
    if (std::getenv("XCFC_DEBUG"))
      std::fprintf(stderr, "composite cycle %d residual %.3e above the floor %.3e (target %.3e)\n", st.cycles, r.max,
                   r.above_floor, s.tolerance * st.scale);
  }
  const double res = r.max;
  st.residual = res;
  st.converged = r.above_floor <= s.tolerance * st.scale;
  st.factor = st.cycles > 0 && st.initial_residual > 0 ? std::pow(res / st.initial_residual, 1.0 / st.cycles) : 0.0;
  st.relaxed_cells = m.relaxed_finest, st.relaxed_cells_all = m.relaxed_all;  // patches only (refined levels)
  m.store(u);
  return st;
}

double CompositeMultigrid::residual_norm(const CompositeEquation& eq, const CompositeField& u) {
  Impl& m = *impl_;
  if (!m.refined()) return m.base.residual_norm(m.base_equation(eq), u.part.at(0));
  m.set_equation(eq);
  m.load(u, eq.nonlinear());
  const auto par = parity_factors(eq.boundary);
  m.restrict_solution(eq.boundary, par);
  return m.leaf_residual(eq.boundary, par).max;
}

}  // namespace remnant::xcfc
