// FAS multigrid (see include/XCFC/multigrid/multigrid.hpp): the level hierarchy, the equation
// coefficients on every level and the public interface. Smoothing and cycles live beside it
// (multigrid_smoothing.cpp, multigrid_cycles.cpp), kernels in boundary_ghosts (ghost cells),
// line_relaxation (line solves), transfers (restriction and prolongation), level_ops (operator
// helpers) and work_partition (the MPI split of the work: every cell update reads exactly the
// values it reads in the serial code, in the same order, so results are bit-identical for any rank
// count).
#include <algorithm>
#include <cmath>

#include "boundary_ghosts.hpp"
#include "level_ops.hpp"
#include "line_relaxation.hpp"
#include "line_relaxation_3d.hpp"
#include "multigrid_impl.hpp"
#include "transfers.hpp"

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

Multigrid::Impl::Impl(const GridShape& shape, MPI_Comm c, MultigridStorage storage) : work(c) {
  levels.emplace_back(shape);
  {
    const Level& L = levels[0];
    frames = CellFrames::of(shape.coordinates, L.ghosted_size, [&](auto&& visit) {
      for (int k = -L.g[2]; k < shape.n[2] + L.g[2]; ++k)
        for (int j = -L.g[1]; j < shape.n[1] + L.g[1]; ++j)
          for (int i = -L.g[0]; i < shape.n[0] + L.g[0]; ++i)
            visit(static_cast<std::size_t>(L.at(i, j, k)), shape.point(i, j, k));
    });
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
  // 2D levels at the spherical origin: rank 0 relaxes the shells' extra theta-line passes alone,
  // once per relaxation of (by default) two sweeps, so it takes that many fewer theta lines of each
  // sweep's pass (the bits do not depend on who solves a line; only the balance does).
  std::vector<int> rank0_extra(levels.size(), 0);
  constexpr int kSweeps = SolveSettings{}.pre_sweeps;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const GridShape& s = levels[l].shape;
    if (s.dimension == 2 && s.boundary[0][0] == Boundary::origin)
      rank0_extra[l] = kOriginPasses * origin_shells(levels[l]) / kSweeps;
  }
  work.build(levels, rank0_extra, storage == MultigridStorage::distributed);
  for (std::size_t l = 0; l < levels.size(); ++l)
    if (work.part(l).windowed) levels[l].set_window(work.part(l).lo, work.part(l).hi);
  line_splits.resize(levels.size());
}

void Multigrid::Impl::add_mode_term(Level& L, AngularMode mode) {
  L.k = L.k_eq;
  if (mode == AngularMode::none) return;
  const auto& mk = L.mode_k[static_cast<int>(mode)];
  if (mk.empty()) {  // a geometry without this mode's term (Level::Level): its term is zero
    for (double& k : L.k) k += 0.0;
    return;
  }
  for (std::size_t q = 0; q < L.k.size(); ++q) L.k[q] += mk[q];
}

void Multigrid::Impl::copy_window(const std::vector<double>& whole, std::vector<double>& out) const {
  const Level& L0 = levels[0];
  const auto b = whole.begin() + static_cast<std::ptrdiff_t>(L0.cbase);
  out.assign(b, b + static_cast<std::ptrdiff_t>(L0.stored_cells));
}

void Multigrid::Impl::set_fine_equation(const ScalarEquation& eq) {
  Level& L0 = levels[0];
  const std::size_t n = L0.stored_cells;
  auto copy = [&](const std::vector<double>& v, std::vector<double>& out) {
    if (v.empty()) out.assign(n, 0.0);
    else copy_window(v, out);
  };
  copy(eq.k, L0.k_eq);
  copy(eq.s0, L0.s0);
  if (eq.s1.empty()) L0.s1.clear(); else copy_window(eq.s1, L0.s1);
  if (eq.s7.empty()) L0.s7.clear(); else copy_window(eq.s7, L0.s7);
  add_mode_term(L0, eq.mode);
  L0.f.assign(n, 0.0);
  L0.r.resize(n);
  if (L0.u.size() != L0.stored_ghosted) L0.u.assign(L0.stored_ghosted, 0.0);
  L0.factored = false;
  equations_ready = Ready::none;
}

void Multigrid::Impl::set_coarse_equations(const ScalarEquation& eq, bool fine_only) {
  if (equations_ready == Ready::all || (fine_only && equations_ready == Ready::fine)) return;
  const bool zero_k = FactorCache::zero_k(eq);
  // A 1D line solve uses level 0 only: no restrictions, and only its lines factored unless the
  // factor cache keeps every level's factors (computed once per equation kind).
  const bool factor_all = !fine_only || FactorCache::eligible(eq);
  for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
    Level &F = levels[l], &C = levels[l + 1];
    if (fine_only) {
      // The cache's factors of every level need each level's k (zeros and the mode term).
      if (factor_all) C.k_eq.assign(C.stored_cells, 0.0), add_mode_term(C, eq.mode);
      continue;
    }
    // Once per solve; the coarse equations are complete on every rank afterwards (the lines across
    // the slabs and the undistributed levels below read all of them). A distributed coarse level
    // restricts its own slab (nested in the fine one's) and gathers the rest: each coarse cell sums
    // the same fine cells in the same order, so the bits do not depend on the rank count.
    // Distributed storage: split levels restrict their own slabs and keep them; the level below the
    // split is agglomerated (each rank restricts under its fine slab, MPI_Allgatherv the rest).
    const bool split = work.part(l + 1).dist, agg = work.part(l + 1).agglomerated;
    const Range RF = split || agg ? work.range(l) : work.full(l), RC = split || agg ? work.restricted_range(l + 1) : work.full(l + 1);
    auto restricted = [&](const std::vector<double>& fine, std::vector<double>& coarse) {
      restrict_interior(F, C, fine, coarse, RF, RC);
      restricted_cells += static_cast<long long>(F.shape.n[0]) * (RF.j1 - RF.j0) * (RF.k1 - RF.k0);
      if (agg) work.agglomerate(l + 1, coarse, false);
      else if (!work.part(l + 1).windowed) work.replicate(l + 1, coarse, false);
    };
    // No matter coefficient: zeros restrict to zeros (the same bits, none of the work).
    if (zero_k) C.k_eq.assign(C.stored_cells, 0.0);
    else restricted(F.k_eq, C.k_eq);
    restricted(F.s0, C.s0);
    if (F.s1.empty()) C.s1.clear(); else restricted(F.s1, C.s1);
    if (F.s7.empty()) C.s7.clear(); else restricted(F.s7, C.s7);
    add_mode_term(C, eq.mode);
    C.f.resize(C.stored_cells);
    C.r.resize(C.stored_cells);
    if (C.u.size() != C.stored_ghosted) C.u.assign(C.stored_ghosted, 0.0);
  }
  if (!factor_cache.acquire(levels, eq)) {
    const std::size_t factored_levels = factor_all ? levels.size() : 1;
    for (std::size_t l = 0; l < factored_levels; ++l) {
      Level& L = levels[l];
      set_line_ends(L, eq);
      if (L.shape.dimension == 3 && L.shape.coordinates != CoordinateSystem::cartesian) factor_lines_3d(L, eq);
      else factored_cells += factor_own_lines(l);
    }
    factor_cache.computed(levels);
  }
  equations_ready = fine_only ? Ready::fine : Ready::all;
}

long long Multigrid::Impl::factor_own_lines(std::size_t l) {
  Level& L = levels[l];
  const auto& p = work.part(l);
  if (!p.dist || L.shape.dimension != 2 || p.s != 1) return factor_lines(L);
  // Lines along i (indexed by j): the own slab; along j (indexed by i): the own line split, and on
  // rank 0 also the origin shells it relaxes for everyone (relax_origin_shells).
  const int along_j_end = work.rank() == 0 ? std::max(p.line_hi, origin_shells(L)) : p.line_hi;
  return factor_lines(L, {p.lo, p.line_lo}, {p.hi, along_j_end});
}

int Multigrid::Impl::origin_shells(const Level& L) {
  // At most n0 / 16 shells: on radially coarse grids 1/dtheta is a large part of the level.
  const int n0 = L.shape.n[0], angular = static_cast<int>(std::ceil(1.0 / L.shape.dx[1]));
  return std::min({std::max(4, angular), std::max(4, n0 / 16), n0});
}

GhostBox Multigrid::Impl::rows_box(std::size_t l) const {
  GhostBox box;
  const auto& p = work.part(l);
  if (p.dist) box.b[static_cast<std::size_t>(p.s)] = p.lo - 1, box.e[static_cast<std::size_t>(p.s)] = p.hi + 1;
  return box;
}

GhostBox Multigrid::Impl::columns_box(std::size_t l, int c0, int c1) const {
  GhostBox box;
  if (work.part(l).dist) box.b[0] = c0 - 1, box.e[0] = c1 + 1;
  return box;
}

double Multigrid::Impl::max_abs_owned(std::size_t l, const std::vector<double>& a) const {
  const auto& p = work.part(l);
  std::size_t b = 0, e = a.size();
  if (p.dist) {  // the owned planes, the domain's ghost planes with the first and last slab
    const auto plane = static_cast<std::size_t>(p.plane), base = static_cast<std::size_t>(p.gbase);
    if (work.rank() > 0) b = static_cast<std::size_t>(p.lo + 1) * plane - base;
    if (work.rank() + 1 < work.nranks()) e = static_cast<std::size_t>(p.hi + 1) * plane - base;
  }
  double m = 0;
  for (std::size_t q = b; q < e; ++q) m = std::max(m, std::abs(a[q]));
  return work.global_max(m);  // a max is exact in any order
}

// A windowed level 0 loads and stores its own cells (q + cbase: their index in the whole array).
void Multigrid::Impl::load(const std::vector<double>& u) {
  Level& L = levels[0];
  const std::size_t b = L.cbase;
  for_cells(L, L.windowed() ? work.range(0) : full_range(L),
            [&](std::size_t q, std::ptrdiff_t p) { L.u[static_cast<std::size_t>(p)] = u[q + b]; });
}

void Multigrid::Impl::store(std::vector<double>& u) const {
  const Level& L = levels[0];
  const std::size_t b = L.cbase;
  for_cells(L, L.windowed() ? work.range(0) : full_range(L),
            [&](std::size_t q, std::ptrdiff_t p) { u[q + b] = L.u[static_cast<std::size_t>(p)]; });
}

void Multigrid::Impl::store_complete(std::vector<double>& u) {
  Level& L = levels[0];
  if (L.windowed()) {
    store(u);
    work.replicate(0, u, false);  // the other ranks' slabs (exact copies)
  } else {
    work.replicate(0, L.u, true);
    store(u);
  }
}

Multigrid::Multigrid(const GridShape& shape, MPI_Comm comm, MultigridStorage storage)
    : impl_(std::make_unique<Impl>(shape, comm, storage)) {}
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

long long Multigrid::reused_factorisations() const { return impl_->factor_cache.hits(); }
long long Multigrid::received_bytes() const { return impl_->work.received_bytes(); }
long long Multigrid::stored_bytes() const {
  const Impl& m = *impl_;
  std::size_t n = m.frames.J.capacity() * sizeof(Matrix3) + m.frames.f.capacity() * sizeof(Point3);
  return static_cast<long long>(n) + level_bytes();
}
long long Multigrid::level_bytes() const {
  const Impl& m = *impl_;
  std::size_t n = 0;
  for (const Level& L : m.levels) n += L.stored_bytes();
  for (const auto& p : m.work.all_parts())
    for (const auto* v : {&p.sbuf, &p.rbuf, &p.gbuf, &p.tsend, &p.trecv}) n += v->capacity() * sizeof(double);
  return static_cast<long long>(n);
}

SolveStats Multigrid::solve(const ScalarEquation& eq, std::vector<double>& u, const SolveSettings& s) {
  Impl& m = *impl_;
  const std::size_t n = m.levels[0].cells();
  if (u.size() != n) u.assign(n, eq.nonlinear() ? 1.0 : 0.0);
  m.set_fine_equation(eq);
  m.load(u);
  m.relaxed_fine = m.relaxed_all = 0;
  m.ghost_entries = m.factored_cells = m.restricted_cells = 0;
  SolveStats st;
  Level& L = m.levels[0];
  // No sources, no boundary values: the solution is zero (no cycles spent on round-off).
  // (The equation's whole s0, not level 0's: a window's zeros must not decide for every rank.)
  const bool trivial = !eq.dirichlet && eq.far_value == 0.0 && !eq.nonlinear() &&
                       std::all_of(eq.s0.begin(), eq.s0.end(), [](double v) { return v == 0.0; });
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
    const double umax = m.max_abs_owned(0, L.u);
    return 256 * std::numeric_limits<double>::epsilon() * L.max_diagonal * umax;
  };
  const double noise = floor();
  static const bool debug = std::getenv("XCFC_DEBUG") != nullptr;
  while (res > std::max(s.tolerance * st.scale, noise) && st.cycles < s.max_cycles) {
    m.set_coarse_equations(eq, line_solve);
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
  st.ghost_entries = m.ghost_entries, st.factored_cells = m.factored_cells, st.restricted_cells = m.restricted_cells;
  m.store_complete(u);  // the solution complete on every rank
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
  const GridShape& s = L.shape;
  std::vector<double> a(L.ghosted_size, 0.0);  // the whole level: global offsets
  std::size_t q = 0;
  for (int k = 0; k < s.n[2]; ++k)
    for (int j = 0; j < s.n[1]; ++j)
      for (int i = 0; i < s.n[0]; ++i) a[static_cast<std::size_t>(L.global_at(i, j, k))] = u[q++];
  fill_ghosts(L, eq, a, false, GhostBox{}, 0);
  return a;
}

void Multigrid::prepare(const ScalarEquation& eq) { impl_->set_fine_equation(eq); }

void Multigrid::cycle(const ScalarEquation& eq, std::vector<double>& u, const std::vector<double>& f,
                      const SolveSettings& s) {
  Impl& m = *impl_;
  Level& L = m.levels[0];
  m.load(u);
  m.copy_window(f, L.f);
  const bool line_solve = s.direct_1d && L.shape.dimension == 1;
  m.set_coarse_equations(eq, line_solve);
  if (line_solve) m.smooth_lines(0, eq, 0);
  else m.vcycle(0, eq, s);
  m.store_complete(u);
}

std::ptrdiff_t Multigrid::ghosted_index(int i, int j, int k) const { return impl_->levels[0].global_at(i, j, k); }
std::array<std::ptrdiff_t, 3> Multigrid::ghosted_strides() const { return impl_->levels[0].st; }
const CellFrames& Multigrid::frames() const { return impl_->frames; }

}  // namespace remnant::xcfc
