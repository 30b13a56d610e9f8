// Cycles of the FAS multigrid (multigrid_impl.hpp): residuals and their scale, the coarsest
// level's solve, the V-cycle and full multigrid.
#include <algorithm>
#include <cmath>

#include "boundary_ghosts.hpp"
#include "level_ops.hpp"
#include "multigrid_impl.hpp"
#include "point_relaxation.hpp"
#include "transfers.hpp"

namespace remnant::xcfc {

double Multigrid::Impl::residual(std::size_t l, const ScalarEquation& eq) {
  Level& L = levels[l];
  work.halo(l, L.u);
  count_fill(L, eq, L.u, false, rows_box(l));
  const Range R = work.range(l);
  apply_operator(L, L.u, L.r, R);
  double m = 0;
  double* r = L.r.data();
  const double* f = L.f.data();
  for_cells(L, R, [&](std::size_t q, std::ptrdiff_t) {
    r[q] = f[q] - r[q];
    m = std::max(m, std::abs(r[q]));
  });
  return work.global_max(m);
}

double Multigrid::Impl::source_scale(std::size_t l) const {
  const Level& L = levels[l];
  const Ops o(L);
  double m = 0;
  for_cells(L, work.range(l), [&](std::size_t q, std::ptrdiff_t p) {
    const double u = L.u[static_cast<std::size_t>(p)];
    double t = std::abs(o.k[q] * u) + std::abs(o.s0[q]);
    if (o.s1) t += std::abs(o.s1[q] / u);
    if (o.s7) {
      const double u2 = u * u, u3 = u2 * u;
      t += std::abs(o.s7[q] / (u3 * u3 * u));
    }
    m = std::max(m, t);
  });
  return work.global_max(m);
}

void Multigrid::Impl::coarse_solve(std::size_t l, const ScalarEquation& eq, int max_sweeps) {
  Level& L = levels[l];
  const double r0 = residual(l, eq);
  if (L.shape.dimension == 1) {
    for (int done = 0; done < max_sweeps; ++done) {
      smooth_lines(l, eq, 0);
      if (residual(l, eq) <= 1e-8 * r0) break;
    }
    return;
  }
  const int chunk = L.cells() <= 64 ? 2 : 10;  // tiny levels: check often, residuals are cheap
  // Stop also once a chunk of sweeps no longer lowers a residual already below 1e-5 of the
  // initial one: the round-off floor, which a small initial residual puts above 1e-8 of it (the
  // 3D curvilinear coarsest levels spent thousands of sweeps there).
  double previous = r0;
  for (int done = 0; done < max_sweeps; done += chunk) {
    relax(l, eq, chunk);
    const double r = residual(l, eq);
    if (r <= 1e-8 * r0 || (r >= previous && r < 1e-5 * r0)) break;
    previous = r;
  }
}

void Multigrid::Impl::vcycle(std::size_t l, const ScalarEquation& eq, const SolveSettings& s) {
  Level& F = levels[l];
  if (l + 1 == levels.size()) {
    coarse_solve(l, eq, std::max(s.coarse_sweeps, 20 * static_cast<int>(F.cells())));
    return;
  }
  Level& C = levels[l + 1];
  relax(l, eq, s.pre_sweeps);
  residual(l, eq);
  // A coarse level computed by every rank needs the whole fine level on every rank; with
  // distributed storage each rank restricts its slab into it instead and the rest is gathered.
  const bool agg = work.part(l + 1).agglomerated;
  if (!work.part(l + 1).dist && !agg) work.replicate(l, F.u, true), work.replicate(l, F.r, false);
  const Range RF = work.part(l + 1).dist || agg ? work.range(l) : work.full(l), RC = work.range(l + 1);
  const Range RR = work.restricted_range(l + 1);  // RC, or the agglomerated level's planes under RF
  restrict_ghosted(F, C, F.u, C.u, RF, RR);
  work.agglomerate(l + 1, C.u, true);
  work.halo(l + 1, C.u);
  count_fill(C, eq, C.u, false, rows_box(l + 1));
  C.ubar = C.u;
  restrict_interior(F, C, F.r, C.f, RF, RR);
  work.agglomerate(l + 1, C.f, false);
  apply_operator(C, C.ubar, C.r, RC);  // C.r as scratch: the coarse cycle recomputes it before use
  for_cells(C, RC, [&](std::size_t q, std::ptrdiff_t) { C.f[q] += C.r[q]; });
  // 2D: the lines along the split direction read f across all slabs.
  if (C.shape.dimension == 2) work.replicate(l + 1, C.f, false);
  vcycle(l + 1, eq, s);
  // The correction on the owned planes (all of a level that is not split), then its halos.
  const auto& pc = work.part(l + 1);
  const std::size_t p0 = pc.dist ? static_cast<std::size_t>((pc.lo + 1) * pc.plane - pc.gbase) : 0;
  const std::size_t p1 = pc.dist ? static_cast<std::size_t>((pc.hi + 1) * pc.plane - pc.gbase) : C.u.size();
  for (std::size_t p = p0; p < p1; ++p) C.ubar[p] = C.u[p] - C.ubar[p];
  work.halo(l + 1, C.ubar);
  count_fill(C, eq, C.ubar, true, rows_box(l + 1));
  prolong(C, F, C.ubar, F.u, false, work.range(l));
  relax(l, eq, s.post_sweeps);
}

void Multigrid::Impl::full_multigrid(const ScalarEquation& eq, const SolveSettings& s) {
  set_coarse_equations(eq);
  // The initial guess down the hierarchy by every rank (the finest level is complete), or with
  // distributed storage by each rank on its slabs (the level below them agglomerated).
  for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
    const bool own = work.part(l).windowed;
    restrict_ghosted(levels[l], levels[l + 1], levels[l].u, levels[l + 1].u, own ? work.range(l) : work.full(l),
                     own ? work.restricted_range(l + 1) : work.full(l + 1));
    work.agglomerate(l + 1, levels[l + 1].u, true);
  }
  for (auto& L : levels) std::fill(L.f.begin(), L.f.end(), 0.0);
  coarse_solve(levels.size() - 1, eq, std::max(s.coarse_sweeps, 20 * static_cast<int>(levels.back().cells())));
  for (std::size_t l = levels.size() - 1; l-- > 0;) {
    work.halo(l + 1, levels[l + 1].u);
    count_fill(levels[l + 1], eq, levels[l + 1].u, false, rows_box(l + 1));
    prolong(levels[l + 1], levels[l], levels[l + 1].u, levels[l].u, true, work.range(l));
    for (std::size_t m = l; m < levels.size(); ++m) std::fill(levels[m].f.begin(), levels[m].f.end(), 0.0);
    vcycle(l, eq, s);
  }
  if (!work.part(0).windowed) work.replicate(0, levels[0].u, true);
}

}  // namespace remnant::xcfc
