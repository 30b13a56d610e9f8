// FAS multigrid (see include/XCFC/multigrid.hpp): the level hierarchy, red-black Newton-Gauss-
// Seidel and zebra line smoothing, V-cycles and full multigrid. Kernels live beside it:
// boundary_ghosts (ghost cells), line_relaxation (line solves), transfers (restriction and
// prolongation), level_ops (operator helpers) and work_partition (the MPI split of the work: every
// cell update reads exactly the values it reads in the serial code, in the same order, so results
// are bit-identical for any rank count).
#include "XCFC/multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "boundary_ghosts.hpp"
#include "level.hpp"
#include "level_ops.hpp"
#include "line_relaxation.hpp"
#include "line_relaxation_3d.hpp"
#include "point_relaxation.hpp"
#include "shell_relaxation.hpp"
#include "transfers.hpp"
#include "work_partition.hpp"

namespace remnant::xcfc {

namespace {
// Whether direction d of a level is coarsened 2:1: an even count of at least 4. A periodic phi is
// never coarsened (semi-coarsening): its coupling is strong next to the axis, where the cyclic phi
// lines solve it, and weak far from it, where modes oscillating in phi but smooth in the other
// directions must stay on the coarse levels (coarsening phi there stalled the V-cycle at 0.87 per
// cycle for a TOV star on a cylindrical 64 x 64 x 8 grid).
bool coarsens(const GridShape& s, int d) {
  return s.n[d] % 2 == 0 && s.n[d] >= 4 && s.boundary[d][0] != Boundary::periodic;
}
}  // namespace

struct Multigrid::Impl {
  std::vector<Level> levels;
  CellFrames frames;
  WorkPartition work;
  long long relaxed_fine = 0, relaxed_all = 0;  // this rank's relaxed cells in the current solve

  Impl(const GridShape& shape, MPI_Comm c) : work(c) {
    levels.emplace_back(shape);
    {
      const Level& L = levels[0];
      frames.J.assign(L.ghosted_size, Matrix3{});
      frames.f.assign(L.ghosted_size, Point3{1, 1, 1});
      for (int k = -L.g[2]; k < shape.n[2] + L.g[2]; ++k)
        for (int j = -L.g[1]; j < shape.n[1] + L.g[1]; ++j)
          for (int i = -L.g[0]; i < shape.n[0] + L.g[0]; ++i) {
            const Point3 x = shape.point(i, j, k);
            const auto p = static_cast<std::size_t>(L.at(i, j, k));
            frames.J[p] = coords::jacobian(shape.coordinates, x);
            frames.f[p] = coords::metric_diagonal(shape.coordinates, x);
          }
    }
    for (;;) {
      const GridShape& s = levels.back().shape;
      GridShape c = s;
      bool coarsened = false;
      std::array<int, 3> ratio{1, 1, 1};
      for (int d = 0; d < 3; ++d)
        if (s.used(d) && coarsens(s, d)) {
          ratio[d] = 2;
          c.n[d] = s.n[d] / 2;
          c.dx[d] = 2 * s.dx[d];
          coarsened = true;
        }
      if (!coarsened) break;
      levels.back().ratio = ratio;
      levels.emplace_back(c);
    }
    // Restriction weights: the fine volumes summed per coarse cell (in the order of restriction).
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
      const Level& F = levels[l];
      Level& C = levels[l + 1];
      C.restrict_volume.assign(C.cells(), 0.0);
      const GridShape& fs = F.shape;
      for (int k = 0; k < fs.n[2]; ++k)
        for (int j = 0; j < fs.n[1]; ++j)
          for (int i = 0; i < fs.n[0]; ++i)
            C.restrict_volume[C.cell(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2])] += F.volume[F.cell(i, j, k)];
    }
    work.build(levels);
    line_splits.resize(levels.size());
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void count(std::size_t l, long long n) {
    relaxed_all += n;
    if (l == 0) relaxed_fine += n;
  }

  // r = f - A(u) on the owned cells; returns max|r| over all ranks (a max is exact in any order).
  double residual(std::size_t l, const ScalarEquation& eq) {
    Level& L = levels[l];
    work.halo(l, L.u);
    fill_ghosts(L, eq, L.u, false);
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

  // Max of the source terms' magnitudes at u: the scale of the residual.
  double source_scale(std::size_t l) const {
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

  // Red-black Gauss-Seidel, one Newton step per cell. A colour's cells read only the other colour:
  // with the halo planes exchanged between colours, the owned slab is updated as in one rank.
  void smooth(std::size_t l, const ScalarEquation& eq, int sweeps) {
    Level& L = levels[l];
    const Range R = work.range(l);
    long long n = 0;
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int colour = 0; colour < 2; ++colour) {
        work.halo(l, L.u);
        fill_ghosts(L, eq, L.u, false);
        n += red_black_pass(L, R, colour);
      }
    count(l, n);
  }

  // One zebra pass. Distributed 2D levels: lines across the slabs (d = s) are local to the slab and
  // need the halo rows between colours; lines along s cross the slabs, so they are solved whole,
  // split by i, from a complete level (Allgatherv), with the neighbouring lines exchanged between
  // colours and the result made complete again.
  // Lines t < limit only: the local relaxation next to the origin.
  void smooth_lines(std::size_t l, const ScalarEquation& eq, int d, int limit = std::numeric_limits<int>::max()) {
    Level& L = levels[l];
    const auto& p = work.part(l);
    const Lines ln(L, d);
    const bool along = p.dist && d == p.s;
    int t0 = 0, t1 = ln.count;
    if (along) t0 = p.line_lo, t1 = p.line_hi, work.replicate(l, L.u, true);
    else if (p.dist) t0 = p.lo, t1 = p.hi;
    t1 = std::max(t0, std::min(t1, limit));
    long long n = 0;
    for (int colour = 0; colour < (ln.count > 1 ? 2 : 1); ++colour) {
      if (along) {
        if (colour > 0) work.exchange_columns(l, L.u);
      } else {
        work.halo(l, L.u);
      }
      fill_ghosts(L, eq, L.u, false);
      n += line_pass(L, ln, colour, t0, t1);
    }
    if (along) work.gather_columns(l, L.u);
    count(l, n);
  }

  // Local relaxation next to the spherical origin (Brandt): the large coefficients there leave the
  // largest residual after a red-black sweep, which otherwise dominates the L-infinity stopping
  // test for V-cycles after the rest of the grid has converged.
  void relax_origin(std::size_t l, const ScalarEquation& eq) {
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

  // 3D cylindrical and spherical levels: zebra lines along d. Every rank holds the whole level and
  // does the rest of the cycle itself; on large levels the lines of each colour are dealt out in
  // contiguous index ranges and the solved lines gathered by every rank (MPI_Allgatherv), so that
  // each line is solved from the same inputs as on one rank: the same bits.
  void smooth_lines_3d(std::size_t l, const ScalarEquation& eq, int d) {
    Level& L = levels[l];
    const int P = work.nranks(), me = work.rank();
    const bool split = P > 1 && L.cells() >= WorkPartition::kMinCells;
    const std::size_t lines = L.cells() / static_cast<std::size_t>(L.shape.n[d]);
    auto cut = [&](int r) { return lines * static_cast<std::size_t>(r) / static_cast<std::size_t>(P); };
    long long n = 0;
    for (int colour = 0; colour < 2; ++colour) {
      fill_ghosts(L, eq, L.u, false);
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
      std::size_t at = 0;
      for (int r = 0; r < P; ++r) at = unpack_lines_3d(L, d, colour, cut(r), cut(r + 1), line_recv, at);
    }
    count(l, n);
  }
  std::vector<double> line_send, line_recv;  // 3D line exchange buffers
  struct LineSplit {
    std::vector<int> counts, displs;  // MPI_Allgatherv layout of the solved lines
  };
  std::vector<std::array<std::array<LineSplit, 2>, 3>> line_splits;  // [level][direction][colour]

  // Point red-black smoothing in 1D and 3D Cartesian, alternating line smoothing in 2D and on 3D
  // cylindrical and spherical levels (strong phi coupling at the axis, angular at the origin).
  void relax(std::size_t l, const ScalarEquation& eq, int sweeps) {
    const GridShape& s = levels[l].shape;
    if (s.dimension == 3 && s.coordinates != CoordinateSystem::cartesian) {
      for (int sweep = 0; sweep < sweeps; ++sweep)
        for (int d = 0; d < 3; ++d) smooth_lines_3d(l, eq, d);
      // Next to the spherical origin: plane relaxation of the shells whose angular coupling
      // exceeds the radial one (i < 1/dtheta; V-cycle factors 0.85 -> 0.04 on 32^3).
      if (s.boundary[0][0] == Boundary::origin && s.boundary[2][0] == Boundary::periodic) {
        fill_ghosts(levels[l], eq, levels[l].u, false);
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
    // relaxation), where the operator's largest coefficients leave the largest residual.
    if (levels[l].shape.boundary[0][0] == Boundary::origin)
      for (int pass = 0; pass < 2; ++pass) smooth_lines(l, eq, 1, std::min(4, levels[l].shape.n[0]));
  }

  // ---- cycles ------------------------------------------------------------------------------------
  // Coarsest level: relaxation to 1e-8 of the initial residual. A 1D level is one line, solved
  // exactly (linear) or by Newton line solves, so it needs no point sweeps at all.
  void coarse_solve(std::size_t l, const ScalarEquation& eq, int max_sweeps) {
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

  void vcycle(std::size_t l, const ScalarEquation& eq, const SolveSettings& s) {
    Level& F = levels[l];
    if (l + 1 == levels.size()) {
      coarse_solve(l, eq, std::max(s.coarse_sweeps, 20 * static_cast<int>(F.cells())));
      return;
    }
    Level& C = levels[l + 1];
    relax(l, eq, s.pre_sweeps);
    residual(l, eq);
    // A coarse level computed by every rank needs the whole fine level on every rank.
    if (!work.part(l + 1).dist) work.replicate(l, F.u, true), work.replicate(l, F.r, false);
    const Range RF = work.part(l + 1).dist ? work.range(l) : work.full(l), RC = work.range(l + 1);
    restrict_ghosted(F, C, F.u, C.u, RF, RC);
    work.halo(l + 1, C.u);
    fill_ghosts(C, eq, C.u, false);
    C.ubar = C.u;
    restrict_interior(F, C, F.r, C.f, RF, RC);
    apply_operator(C, C.ubar, C.r, RC);  // C.r as scratch: the coarse cycle recomputes it before use
    for_cells(C, RC, [&](std::size_t q, std::ptrdiff_t) { C.f[q] += C.r[q]; });
    // 2D: the lines along the split direction read f across all slabs.
    if (C.shape.dimension == 2) work.replicate(l + 1, C.f, false);
    vcycle(l + 1, eq, s);
    // The correction on the owned planes (all of a level that is not split), then its halos.
    const auto& pc = work.part(l + 1);
    const std::size_t p0 = pc.dist ? static_cast<std::size_t>((pc.lo + 1) * pc.plane) : 0;
    const std::size_t p1 = pc.dist ? static_cast<std::size_t>((pc.hi + 1) * pc.plane) : C.u.size();
    for (std::size_t p = p0; p < p1; ++p) C.ubar[p] = C.u[p] - C.ubar[p];
    work.halo(l + 1, C.ubar);
    fill_ghosts(C, eq, C.ubar, true);
    prolong(C, F, C.ubar, F.u, false, work.range(l));
    relax(l, eq, s.post_sweeps);
  }

  void full_multigrid(const ScalarEquation& eq, const SolveSettings& s) {
    set_coarse_equations(eq);
    // The initial guess down the hierarchy by every rank (the finest level is complete).
    for (std::size_t l = 0; l + 1 < levels.size(); ++l)
      restrict_ghosted(levels[l], levels[l + 1], levels[l].u, levels[l + 1].u, work.full(l), work.full(l + 1));
    for (auto& L : levels) std::fill(L.f.begin(), L.f.end(), 0.0);
    coarse_solve(levels.size() - 1, eq, std::max(s.coarse_sweeps, 20 * static_cast<int>(levels.back().cells())));
    for (std::size_t l = levels.size() - 1; l-- > 0;) {
      work.halo(l + 1, levels[l + 1].u);
      fill_ghosts(levels[l + 1], eq, levels[l + 1].u, false);
      prolong(levels[l + 1], levels[l], levels[l + 1].u, levels[l].u, true, work.range(l));
      for (std::size_t m = l; m < levels.size(); ++m) std::fill(levels[m].f.begin(), levels[m].f.end(), 0.0);
      vcycle(l, eq, s);
    }
    work.replicate(0, levels[0].u, true);
  }

  // k = the equation's k plus the geometric point term of its angular mode, which is rediscretised
  // on each level, not restricted.
  static void add_mode_term(Level& L, AngularMode mode) {
    L.k = L.k_eq;
    if (mode == AngularMode::none) return;
    const auto& mk = L.mode_k[static_cast<int>(mode)];
    for (std::size_t q = 0; q < L.k.size(); ++q) L.k[q] += mk[q];
  }

  // Equation coefficients: set_fine_equation on the finest level (all a residual needs);
  // set_coarse_equations on the coarse levels, line ends and line factors everywhere, only once a
  // cycle is needed (a warm start that already meets the tolerance costs one residual).
  void set_fine_equation(const ScalarEquation& eq) {
    Level& L0 = levels[0];
    const std::size_t n = L0.cells();
    auto copy = [&](const std::vector<double>& v, std::vector<double>& out) {
      if (v.empty()) out.assign(n, 0.0);
      else out.assign(v.begin(), v.end());
    };
    copy(eq.k, L0.k_eq);
    copy(eq.s0, L0.s0);
    if (eq.s1.empty()) L0.s1.clear(); else L0.s1.assign(eq.s1.begin(), eq.s1.end());
    if (eq.s7.empty()) L0.s7.clear(); else L0.s7.assign(eq.s7.begin(), eq.s7.end());
    add_mode_term(L0, eq.mode);
    L0.f.assign(n, 0.0);
    L0.r.resize(n);
    if (L0.u.size() != L0.ghosted_size) L0.u.assign(L0.ghosted_size, 0.0);
    L0.factored = false;
    coarse_ready = false;
  }
  void set_coarse_equations(const ScalarEquation& eq) {
    if (coarse_ready) return;
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
      Level &F = levels[l], &C = levels[l + 1];
      // Once per solve, by every rank: the coarse equations are complete everywhere.
      const Range RF = work.full(l), RC = work.full(l + 1);
      restrict_interior(F, C, F.k_eq, C.k_eq, RF, RC);
      restrict_interior(F, C, F.s0, C.s0, RF, RC);
      if (F.s1.empty()) C.s1.clear(); else restrict_interior(F, C, F.s1, C.s1, RF, RC);
      if (F.s7.empty()) C.s7.clear(); else restrict_interior(F, C, F.s7, C.s7, RF, RC);
      add_mode_term(C, eq.mode);
      C.f.resize(C.cells());
      C.r.resize(C.cells());
      if (C.u.size() != C.ghosted_size) C.u.assign(C.ghosted_size, 0.0);
    }
    for (auto& L : levels) {
      set_line_ends(L, eq);
      if (L.shape.dimension == 3 && L.shape.coordinates != CoordinateSystem::cartesian) factor_lines_3d(L, eq);
      else factor_lines(L);
    }
    coarse_ready = true;
  }
  bool coarse_ready = false;

  void load(const std::vector<double>& u) {
    Level& L = levels[0];
    for_cells(L, full_range(L), [&](std::size_t q, std::ptrdiff_t p) { L.u[static_cast<std::size_t>(p)] = u[q]; });
  }
  void store(std::vector<double>& u) const {
    const Level& L = levels[0];
    for_cells(L, full_range(L), [&](std::size_t q, std::ptrdiff_t p) { u[q] = L.u[static_cast<std::size_t>(p)]; });
  }
};

Multigrid::Multigrid(const GridShape& shape, MPI_Comm comm) : impl_(std::make_unique<Impl>(shape, comm)) {}
Multigrid::~Multigrid() = default;
Multigrid::Multigrid(Multigrid&&) noexcept = default;
Multigrid& Multigrid::operator=(Multigrid&&) noexcept = default;

const GridShape& Multigrid::shape() const { return impl_->levels[0].shape; }
int Multigrid::levels() const { return static_cast<int>(impl_->levels.size()); }
int Multigrid::distributed_levels() const {
  int n = 0;
  for (const auto& p : impl_->work.all_parts()) n += p.dist ? 1 : 0;
  return n;
}

SolveStats Multigrid::solve(const ScalarEquation& eq, std::vector<double>& u, const SolveSettings& s) {
  Impl& m = *impl_;
  const std::size_t n = m.levels[0].cells();
  if (u.size() != n) u.assign(n, eq.nonlinear() ? 1.0 : 0.0);
  m.set_fine_equation(eq);
  m.load(u);
  m.relaxed_fine = m.relaxed_all = 0;
  SolveStats st;
  Level& L = m.levels[0];
  // No sources, no boundary values: the solution is zero (no cycles spent on round-off).
  const bool trivial = !eq.dirichlet && eq.far_value == 0.0 && !eq.nonlinear() &&
                       std::all_of(L.s0.begin(), L.s0.end(), [](double v) { return v == 0.0; });
  if (trivial) {
    std::fill(u.begin(), u.end(), 0.0);
    st.converged = true;
    return st;
  }
  // 1D: the whole level is one line, and a line solve is exact for linear equations (Newton for
  // psi), so each "cycle" is one tridiagonal solve on the finest level.
  const bool line_solve = s.direct_1d && L.shape.dimension == 1;
  if (s.full_multigrid && !line_solve) m.full_multigrid(eq, s);
  st.initial_residual = m.residual(0, eq);
  double res = st.initial_residual;
  auto scale = [&] {
    const double sc = std::max(m.source_scale(0), s.scale_floor);
    return sc > 0 ? sc : 1.0;
  };
  st.scale = scale();
  // Round-off floor of the residual: the largest operator term times a few ulps. Near the spherical
  // origin and axis the coefficients are large and a relative 1e-10 can lie below it.
  auto floor = [&] {
    const double m = L.max_diagonal;
    double umax = 0;
    for (double v : L.u) umax = std::max(umax, std::abs(v));
    return 256 * std::numeric_limits<double>::epsilon() * m * umax;
  };
  const double noise = floor();
  static const bool debug = std::getenv("XCFC_DEBUG") != nullptr;
  while (res > std::max(s.tolerance * st.scale, noise) && st.cycles < s.max_cycles) {
    m.set_coarse_equations(eq);
    if (line_solve) m.smooth_lines(0, eq, 0);
    else m.vcycle(0, eq, s);
    ++st.cycles;
    res = m.residual(0, eq);
    st.scale = scale();
    st.history.push_back(res);
    if (debug) {
      std::size_t at = 0;
      for (std::size_t q = 0; q < L.r.size(); ++q) if (std::abs(L.r[q]) > std::abs(L.r[at])) at = q;
      std::fprintf(stderr, "cycle %d residual %.3e at %zu (initial %.3e, target %.3e)\n", st.cycles, res, at, st.initial_residual, s.tolerance * st.scale);
    }
  }
  st.residual = res;
  st.converged = res <= std::max(s.tolerance * st.scale, noise);
  st.factor = st.cycles > 0 && st.initial_residual > 0 ? std::pow(res / st.initial_residual, 1.0 / st.cycles) : 0.0;
  st.relaxed_cells = m.relaxed_fine, st.relaxed_cells_all = m.relaxed_all;
  m.work.replicate(0, L.u, true);  // the solution complete on every rank
  m.store(u);
  return st;
}

double Multigrid::residual_norm(const ScalarEquation& eq, const std::vector<double>& u) {
  Impl& m = *impl_;
  m.set_fine_equation(eq);
  m.load(u);
  return m.residual(0, eq);
}

std::vector<double> Multigrid::with_ghosts(const ScalarEquation& eq, const std::vector<double>& u) const {
  const Level& L = impl_->levels[0];
  std::vector<double> a(L.ghosted_size, 0.0);
  for_cells(L, full_range(L), [&](std::size_t q, std::ptrdiff_t p) { a[static_cast<std::size_t>(p)] = u[q]; });
  fill_ghosts(L, eq, a, false);
  return a;
}

void Multigrid::prepare(const ScalarEquation& eq) { impl_->set_fine_equation(eq); }

void Multigrid::cycle(const ScalarEquation& eq, std::vector<double>& u, const std::vector<double>& f,
                      const SolveSettings& s) {
  Impl& m = *impl_;
  Level& L = m.levels[0];
  m.load(u);
  L.f.assign(f.begin(), f.end());
  m.set_coarse_equations(eq);
  if (s.direct_1d && L.shape.dimension == 1) m.smooth_lines(0, eq, 0);
  else m.vcycle(0, eq, s);
  m.work.replicate(0, L.u, true);
  m.store(u);
}

std::ptrdiff_t Multigrid::ghosted_index(int i, int j, int k) const { return impl_->levels[0].at(i, j, k); }
std::array<std::ptrdiff_t, 3> Multigrid::ghosted_strides() const { return impl_->levels[0].st; }
const CellFrames& Multigrid::frames() const { return impl_->frames; }

}  // namespace remnant::xcfc
