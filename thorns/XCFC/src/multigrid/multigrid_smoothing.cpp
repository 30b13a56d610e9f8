// Smoothing of the FAS multigrid (multigrid_impl.hpp): red-black Newton-Gauss-Seidel, zebra lines
// (2D, 3D curvilinear with the MPI deal of the lines), the local relaxation next to the spherical
// origin and the plane relaxation of the innermost spherical shells.
#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "boundary_ghosts.hpp"
#include "level_ops.hpp"
#include "line_relaxation.hpp"
#include "line_relaxation_3d.hpp"
#include "multigrid_impl.hpp"
#include "point_relaxation.hpp"
#include "remnant/comm_counters.hpp"
#include "shell_relaxation.hpp"

namespace remnant::xcfc {

void Multigrid::Impl::smooth(std::size_t l, const ScalarEquation& eq, int sweeps) {
  Level& L = levels[l];
  const Range R = work.range(l);
  long long n = 0;
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int colour = 0; colour < 2; ++colour) {
      work.halo(l, L.u);
      count_fill(L, eq, L.u, false, rows_box(l));
      n += red_black_pass(L, R, colour);
    }
  count(l, n);
}

void Multigrid::Impl::smooth_lines(std::size_t l, const ScalarEquation& eq, int d, int limit) {
  Level& L = levels[l];
  const auto& p = work.part(l);
  const Lines ln(L, d);
  const bool along = p.dist && d == p.s;
  int t0 = 0, t1 = ln.count;
  if (along) t0 = p.line_lo, t1 = p.line_hi, work.to_columns(l, L.u);
  else if (p.dist) t0 = p.lo, t1 = p.hi;
  t1 = std::max(t0, std::min(t1, limit));
  const GhostBox box = along ? columns_box(l, t0, t1) : rows_box(l);
  long long n = 0;
  for (int colour = 0; colour < (ln.count > 1 ? 2 : 1); ++colour) {
    if (along) {
      if (colour > 0) work.exchange_columns(l, L.u);
    } else {
      work.halo(l, L.u);
    }
    count_fill(L, eq, L.u, false, box);
    n += line_pass(L, ln, colour, t0, t1);
  }
  if (along) work.to_slabs(l, L.u);
  count(l, n);
}

void Multigrid::Impl::relax_origin(std::size_t l, const ScalarEquation& eq) {
  Level& L = levels[l];
  const GridShape& s = L.shape;
  if (s.dimension != 1 || s.boundary[0][0] != Boundary::origin) return;
  count(l, 2 * std::min(s.n[0], 4));
  double* u = L.u.data();
  const Ops o(L);
  const bool nonlinear = o.nonlinear();
  const int m = std::min(s.n[0], 4);
  for (int pass = 0; pass < 2; ++pass) {
    u[L.at(-1, 0, 0)] = eq.parity[0][0] * u[L.at(0, 0, 0)];
    for (int i = 0; i < m; ++i) {
      const std::size_t q = static_cast<std::size_t>(i);
      const std::ptrdiff_t p = L.at(i, 0, 0);
      const double uc = u[p];
      const double res = o.sigma<1>(u, p, q) - o.diag[q] * uc - o.source(q, uc) - o.f[q];
      double un = uc - res / (-o.diag[q] - o.source_derivative(q, uc));
      if (nonlinear && !(un > 0.1 * uc)) un = 0.5 * uc;
      u[p] = un;
      if (i == 0) u[L.at(-1, 0, 0)] = eq.parity[0][0] * un;
    }
  }
}

void Multigrid::Impl::smooth_lines_3d(std::size_t l, const ScalarEquation& eq, int d) {
  Level& L = levels[l];
  const int P = work.nranks(), me = work.rank();
  const bool split = P > 1 && L.cells() >= WorkPartition::kMinCells;
  const std::size_t lines = L.cells() / static_cast<std::size_t>(L.shape.n[d]);
  auto cut = [&](int r) { return lines * static_cast<std::size_t>(r) / static_cast<std::size_t>(P); };
  long long n = 0;
  for (int colour = 0; colour < 2; ++colour) {
    count_fill(L, eq, L.u, false);
    if (!split) {
      n += line_pass_3d(L, eq, d, colour);
      continue;
    }
    n += line_pass_3d(L, eq, d, colour, cut(me), cut(me + 1));
    line_send.clear();
    pack_lines_3d(L, d, colour, cut(me), cut(me + 1), line_send);
    // Cells per rank of this level, direction and colour (geometry: counted once).
    LineSplit& split = line_splits[l][static_cast<std::size_t>(d)][static_cast<std::size_t>(colour)];
    if (split.counts.empty()) {
      split.counts.assign(static_cast<std::size_t>(P), 0);
      split.displs.assign(static_cast<std::size_t>(P), 0);
      for (int r = 0; r < P; ++r) {
        const auto u = static_cast<std::size_t>(r);
        split.counts[u] = static_cast<int>(line_cells_3d(L, d, colour, cut(r), cut(r + 1)));
        if (r > 0) split.displs[u] = split.displs[u - 1] + split.counts[u - 1];
      }
    }
    line_recv.resize(static_cast<std::size_t>(split.displs.back() + split.counts.back()));
    MPI_Allgatherv(line_send.data(), static_cast<int>(line_send.size()), MPI_DOUBLE, line_recv.data(), split.counts.data(),
                   split.displs.data(), MPI_DOUBLE, work.communicator());
    comm::count("mg_base_lines_allgather", comm::Pattern::allgather, static_cast<int>(l), 1,
                static_cast<long long>(sizeof(double) * (line_recv.size() - line_send.size())));
    std::size_t at = 0;
    for (int r = 0; r < P; ++r) at = unpack_lines_3d(L, d, colour, cut(r), cut(r + 1), line_recv, at);
  }
  count(l, n);
}

void Multigrid::Impl::relax(std::size_t l, const ScalarEquation& eq, int sweeps) {
  const GridShape& s = levels[l].shape;
  if (s.dimension == 3 && s.coordinates != CoordinateSystem::cartesian) {
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int d = 0; d < 3; ++d) smooth_lines_3d(l, eq, d);
    // Next to the spherical origin: plane relaxation of the shells whose angular coupling
    // exceeds the radial one (i < 1/dtheta; V-cycle factors 0.85 -> 0.04 on 32^3).
    if (s.boundary[0][0] == Boundary::origin && s.boundary[2][0] == Boundary::periodic) {
      count_fill(levels[l], eq, levels[l].u, false);
      count(l, relax_inner_shells(levels[l], eq, angular_shells(levels[l])));
    }
    return;
  }
  if (levels[l].shape.dimension != 2) {
    smooth(l, eq, sweeps);
    return relax_origin(l, eq);
  }
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int d = 0; d < 2; ++d) smooth_lines(l, eq, d);
  // 2D spherical: extra theta-line passes over the innermost radial cells (Brandt's local
  // relaxation), where the operator's largest coefficients leave the largest residual: every shell
  // whose angular coupling exceeds the radial one (r dtheta < dr: i < 1/dtheta), 8 passes. The
  // warm-started solves of the migration run took 23.8 V-cycles per xCFC solve with 2 passes over
  // 4 shells, 15.0 with these (about 6 % more work per cycle).
  const Level& L = levels[l];
  if (L.shape.boundary[0][0] == Boundary::origin) {
    relax_origin_shells(l, eq, origin_shells(L), kOriginPasses);
  }
}

void Multigrid::Impl::relax_origin_shells(std::size_t l, const ScalarEquation& eq, int shells, int passes) {
  const auto& p = work.part(l);
  // Distributed: the shells' theta lines are whole columns; rank 0 gathers them (and the next
  // column, which their stencil reads), relaxes them and sends them back: two small exchanges
  // instead of two transposes per pass, the same updates in the same order as one rank.
  if (!p.dist || p.s != 1) {
    for (int pass = 0; pass < passes; ++pass) smooth_lines(l, eq, 1, shells);
    return;
  }
  const int ncols = std::min(shells + 1, levels[l].shape.n[0]);
  Level& L = levels[l];
  work.columns_to_root(l, L.u, ncols);
  if (work.rank() == 0) {
    const Lines ln(L, 1);
    long long n = 0;
    for (int pass = 0; pass < passes; ++pass)
      for (int colour = 0; colour < 2; ++colour) {
        count_fill(L, eq, L.u, false, columns_box(l, 0, shells));
        n += line_pass(L, ln, colour, 0, shells);
      }
    count(l, n);
  }
  work.columns_from_root(l, L.u, ncols);
}

}  // namespace remnant::xcfc
