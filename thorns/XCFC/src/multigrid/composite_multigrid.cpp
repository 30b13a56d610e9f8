// Composite FAS multigrid on refined patches (see include/XCFC/multigrid/composite_multigrid.hpp):
// set-up, ghost recipes, equation coefficients and the public interface; the cycle is in
// composite_cycle.cpp. Each level ("tier") is a set of patches, each patch a Level with one ghost
// layer; tier 0 is the base grid as one patch, solved by Multigrid. Ghost values and the coarse
// windows of the prolongation are affine "recipes" in stored interior values, built once per
// boundary signature by resolving symmetry mirrors, outer boundaries and coarse-fine interpolation
// symbolically.
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

#include "composite_impl.hpp"
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

CompositeMultigrid::Impl::Impl(const CompositeLayout& l, MPI_Comm c, MultigridStorage storage)
    : layout(l), base(l.base, c, storage), comm(c) {
  if (comm != MPI_COMM_SELF) {  // MPI_COMM_SELF needs no MPI call (unit tests, benchmarks without MPI_Init)
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &nranks);
  }
  tiers = build_tiers(l, nranks);
  parents_of_own.resize(tiers.size());
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
        g.own = CellFrames::of(P.shape.coordinates, P.ghosted_size, [&](auto&& visit) {
          for (int k = -P.g[2]; k < P.shape.n[2] + P.g[2]; ++k)
            for (int j = -P.g[1]; j < P.shape.n[1] + P.g[1]; ++j)
              for (int i = -P.g[0]; i < P.shape.n[0] + P.g[0]; ++i)
                visit(static_cast<std::size_t>(P.at(i, j, k)), P.shape.point(i, j, k));
        });
      }
      geometry.push_back(std::move(g));
    }
  std::vector<std::size_t> cells, ghosted;
  for (const PartGeometry& g : geometry) cells.push_back(g.shape.cells()), ghosted.push_back(g.frames().points);
  share = CellShare(cells, comm);
  ghosted_share = CellShare(ghosted, comm);
}

void CompositeMultigrid::Impl::expand(int t, Cell I, double w, unsigned mask, double falloff, bool dirichlet, std::vector<Term>& out) const {
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

const Recipes& CompositeMultigrid::Impl::recipes_for(const ScalarEquation& eq) {
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
  // The term list grew by doubling: up to half of it was spare capacity, kept for the whole run
  // (3.5 of the 3D magnetised TOV octant's 14.7 MB for two signatures, then 11.2 MB of 56-byte
  // terms, 6.4 MB as StoredTerm; issue 21, goal 7).
  R.terms.shrink_to_fit();
  R.points.shrink_to_fit();
  return R;
}

std::size_t CompositeMultigrid::recipe_bytes() const {
  std::size_t n = 0;
  for (const auto& [sig, R] : impl_->recipes) {
    n += R.terms.capacity() * sizeof(StoredTerm) + R.points.capacity() * sizeof(Point3);
    for (const auto* lists : {&R.ghosts, &R.window})
      for (const auto& tier : *lists)
        for (const auto& list : tier) n += list.capacity() * sizeof(Recipe);
  }
  return n;
}

void CompositeMultigrid::Impl::add_mode_term(Level& L, AngularMode mode) {
  L.k = L.k_eq;
  if (mode == AngularMode::none) return;
  const auto& mk = L.mode_k[static_cast<int>(mode)];
  if (mk.empty()) {  // a geometry without this mode's term (Level::Level): its term is zero
    for (double& k : L.k) k += 0.0;
    return;
  }
  for (std::size_t q = 0; q < L.k.size(); ++q) L.k[q] += mk[q];
}

void CompositeMultigrid::Impl::set_equation(const CompositeEquation& eq) {
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
    // Each rank restricts its own patches; the footprints of all four go to every rank at once.
    const auto [p0, p1] = own_patches(t);
    std::vector<std::vector<double> Level::*> present;
    for (auto a : {&Level::k_eq, &Level::s0, &Level::s1, &Level::s7}) {
      if ((T.patches[0].*a).empty()) continue;
      present.push_back(a);
      restrict_tier(t, [&](std::size_t p, std::size_t q) { return (T.patches[p].*a)[q]; },
                    [&](std::size_t p, std::size_t q) -> double& { return (C.patches[p].*a)[q]; }, p0, p1);
    }
    exchange_footprint_values(t, static_cast<int>(present.size()), [&](std::size_t parent, int i, int j, int k, auto&& value) {
      Level& Q = C.patches[parent];
      for (auto a : present) value((Q.*a)[Q.cell(i, j, k)]);
    });
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

void CompositeMultigrid::Impl::load(const CompositeField& u, bool nonlinear) {
  for (std::size_t i = 0; i < part_of.size(); ++i) {
    Level& P = tiers[static_cast<std::size_t>(part_of[i].first)].patches[static_cast<std::size_t>(part_of[i].second)];
    P.u.assign(P.ghosted_size, nonlinear ? 1.0 : 0.0);
    if (i < u.part.size() && u.part[i].size() == P.cells())
      for_cells(P, full_range(P), [&](std::size_t q, std::ptrdiff_t g) { P.u[static_cast<std::size_t>(g)] = u.part[i][q]; });
  }
}

void CompositeMultigrid::Impl::store(CompositeField& u) const {
  u.part.resize(part_of.size());
  for (std::size_t i = 0; i < part_of.size(); ++i) {
    const Level& P = tiers[static_cast<std::size_t>(part_of[i].first)].patches[static_cast<std::size_t>(part_of[i].second)];
    u.part[i].resize(P.cells());
    for_cells(P, full_range(P), [&](std::size_t q, std::ptrdiff_t g) { u.part[i][q] = P.u[static_cast<std::size_t>(g)]; });
  }
}

ScalarEquation CompositeMultigrid::Impl::base_equation(const CompositeEquation& eq) const {
  ScalarEquation b = eq.boundary;
  if (!eq.k.empty()) b.k = eq.k.part[0];
  if (!eq.s0.empty()) b.s0 = eq.s0.part[0];
  if (!eq.s1.empty()) b.s1 = eq.s1.part[0];
  if (!eq.s7.empty()) b.s7 = eq.s7.part[0];
  return b;
}

CompositeMultigrid::CompositeMultigrid(const CompositeLayout& layout, MPI_Comm comm, MultigridStorage storage)
    : impl_(std::make_unique<Impl>(layout, comm, storage)) {}
CompositeMultigrid::CompositeMultigrid(const GridShape& shape, MPI_Comm comm, MultigridStorage storage)
    : CompositeMultigrid(CompositeLayout{shape, {1, 1, 1}, {}}, comm, storage) {}
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

const CellShare& CompositeMultigrid::share(bool ghosted) const { return ghosted ? impl_->ghosted_share : impl_->share; }
MPI_Comm CompositeMultigrid::comm() const { return impl_->comm; }
void CompositeMultigrid::complete(std::initializer_list<CompositeField*> fields, bool ghosted) const {
  const CellShare& s = share(ghosted);
  if (!s.split()) return;
  std::vector<std::vector<std::vector<double>>*> parts;
  for (CompositeField* f : fields) parts.push_back(&f->part);
  s.complete(parts);
}

void CompositeMultigrid::fill_covered(CompositeField& f) const {
  // Each rank restricts its own patches (point split) and the footprints are exchanged, finest first.
  const Impl& m = *impl_;
  for (int t = static_cast<int>(m.tiers.size()) - 1; t >= 1; --t) {
    const auto [p0, p1] = m.own_patches(t);
    m.restrict_tier(t, [&](std::size_t p, std::size_t q) { return f.part[m.part_index(t, p)][q]; },
                    [&](std::size_t p, std::size_t q) -> double& { return f.part[m.part_index(t - 1, p)][q]; }, p0, p1);
    const Tier& C = m.tiers[static_cast<std::size_t>(t - 1)];
    m.exchange_footprint_values(t, 1, [&](std::size_t parent, int i, int j, int k, auto&& value) {
      value(f.part[m.part_index(t - 1, parent)][C.patches[parent].cell(i, j, k)]);
    });
  }
}

CompositeField CompositeMultigrid::with_ghosts(const ScalarEquation& boundary, const CompositeField& u, bool share_only) {
  Impl& m = *impl_;
  if (!m.refined()) return {{m.base.with_ghosts(boundary, u.part.at(0))}};
  const auto par = parity_factors(boundary);
  m.load(u, false);
  m.restrict_solution(boundary, par);
  CompositeField out;
  std::vector<int> touched;
  for (int t = 0; t < static_cast<int>(m.tiers.size()); ++t) {
    if (!share_only || m.nranks == 1) {
      m.fill(t, boundary, par);
      continue;
    }
    // Only the parts that this rank's shares (interior or ghosted cells) reach.
    touched.clear();
    for (std::size_t p = 0; p < m.tiers[static_cast<std::size_t>(t)].patches.size(); ++p) {
      const int n = static_cast<int>(m.part_index(t, p));
      const auto [b, e] = m.share.range(n);
      const auto [gb, ge] = m.ghosted_share.range(n);
      if (b < e || gb < ge) touched.push_back(static_cast<int>(p));
    }
    if (t == 0) {
      if (!touched.empty()) m.fill(0, boundary, par);
    } else {
      const Tier::Split S = m.only_these(touched);
      m.fill(t, boundary, par, &S);
    }
  }
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
  m.ghosts_filled = 0;
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
  st.ghost_entries = m.ghosts_filled;  // patch ghosts (recipes) only
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
