#include "stagger_test_util.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

namespace remnant::grid::test {

namespace {

constexpr double kPi = std::numbers::pi;

std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  return h ^ (h >> 33);
}

// A reproducible number in [-1, 1] for an edge along `a` at finest-level index q.
double random_edge(std::uint64_t seed, int a, std::array<std::int64_t, 3> q) {
  std::uint64_t h = mix(seed + 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(a + 1));
  for (auto v : q) h = mix(h ^ static_cast<std::uint64_t>(v + 1000003));
  return static_cast<double>(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

struct Potential {
  const GridConfig& c;
  int finest;
  std::uint64_t seed;
  std::array<std::int64_t, 3> cells_finest{};  // finest-level cells per direction

  // Line integral along the finest edge along a from vertex q (q_a: the cell index along a).
  double finest_edge(int a, std::array<std::int64_t, 3> q) const {
    const int dim = c.dimension;
    if (dim == 2 && a < 2) return 0.0;  // 2D: only the potential along the unused direction
    for (int e = 0; e < dim; ++e)       // periodic directions wrap
      if (c.boundary_lower[static_cast<std::size_t>(e)] == Boundary::periodic)
        q[static_cast<std::size_t>(e)] = ((q[static_cast<std::size_t>(e)] % cells_finest[static_cast<std::size_t>(e)]) +
                                          cells_finest[static_cast<std::size_t>(e)]) % cells_finest[static_cast<std::size_t>(e)];
    if (c.coordinates == CoordinateSystem::cylindrical && q[0] == 0) {
      if (a == 2) return 0.0;  // a circle of radius 0
      if (a == 1) q[2] = 0;    // one value along the axis whatever phi
    }
    if (c.coordinates == CoordinateSystem::spherical) {
      if (q[0] == 0 && a != 0) return 0.0;  // the origin
      const bool axis = dim >= 2 && (q[1] == 0 || q[1] == cells_finest[1]);
      if (axis && a == 2) return 0.0;
      if (axis && a == 0) q[2] = 0;
    }
    return random_edge(seed, a, q);
  }

  // Line integral along the level-l edge along a from vertex p: the sum of its finest edges.
  double edge(int level, int a, const std::array<std::int64_t, 3>& p) const {
    const std::int64_t r = std::int64_t{1} << (finest - level);
    std::array<std::int64_t, 3> q{};
    for (int e = 0; e < 3; ++e) q[static_cast<std::size_t>(e)] = e < c.dimension ? p[static_cast<std::size_t>(e)] * r : p[static_cast<std::size_t>(e)];
    if (a >= c.dimension) return finest_edge(a, q);
    double s = 0;
    for (std::int64_t m = 0; m < r; ++m) {
      auto qm = q;
      qm[static_cast<std::size_t>(a)] += m;
      s += finest_edge(a, qm);
    }
    return s;
  }

  // Circulation around the face normal to d whose lowest vertex is p (level l).
  double flux(int level, int d, const std::array<std::int64_t, 3>& p) const {
    const int a = (d + 1) % 3, b = (d + 2) % 3;
    auto plus = [&](int e) {
      auto q = p;
      q[static_cast<std::size_t>(e)] += 1;
      return q;
    };
    return edge(level, a, p) + edge(level, b, plus(a)) - edge(level, a, plus(b)) - edge(level, b, p);
  }
};

// A covariant EMF pattern that differs between levels (as a scheme's EMFs do) and, by the factor
// `variant`, between blocks, periodic in the third coordinate, zero along edges of zero length and
// single-valued along an axis (no correction crosses an axis: a thorn must compute it so).
double emf(CoordinateSystem coords, int level, int a, Point3 x, double variant) {
  const bool at_axis = coords == CoordinateSystem::cylindrical ? x[0] == 0
                     : coords == CoordinateSystem::spherical && (x[1] == 0 || std::abs(x[1] - std::numbers::pi) < 1e-12);
  if (coords == CoordinateSystem::spherical && x[0] == 0 && a != 0) return 0.0;
  if (at_axis && a == 2) return 0.0;
  if (at_axis) x[2] = 0;
  // Blocks' own variants, but one value along an axis (a thorn must compute it so: no correction
  // crosses an axis).
  return (1 + a) * std::sin(2.1 * x[0] + 0.3 * a) * std::cos(1.7 * x[1] - 0.2) * (1.2 + 0.3 * std::cos(x[2])) *
         (1 + 0.1 * level * (1 + x[0] * x[1])) * (at_axis ? 1.0 : variant);
}

}  // namespace

FaceField make_face_field() {
  FaceField f;
  const Centering cs[3] = {Centering::face_x, Centering::face_y, Centering::face_z};
  const char* names[3] = {"Bx", "By", "Bz"};
  for (int d = 0; d < 3; ++d) {
    VariableGroupSpec g;
    g.thorn = "Test";
    g.name = names[d];
    g.centering = cs[d];
    g.components = expand_tensor(TensorKind::scalar, names[d]);
    g.role = VariableRole::evolved;
    g.rhs = std::string(names[d]) + "_rhs";
    g.prolongation = "divergence_preserving";
    f.group[d] = f.vars.add(std::move(g));
  }
  return f;
}

DomainBounds full_domain(CoordinateSystem coords) {
  switch (coords) {
    case CoordinateSystem::cartesian: return {{-1, -1, -1}, {1, 1, 1}};
    case CoordinateSystem::cylindrical: return {{0, -1, 0}, {1, 1, 2 * kPi}};
    case CoordinateSystem::spherical: return {{0, 0, 0}, {1, kPi, 2 * kPi}};
  }
  return {};
}

GridConfig stagger_config(CoordinateSystem coords, int dim) {
  GridConfig c;
  c.coordinates = coords;
  c.dimension = dim;
  c.ncells = {16, 16, 16};
  c.block_size = {8, 8, 8};
  c.ghost_zones = 2;
  c.max_level = 2;
  const DomainBounds domain = full_domain(coords);
  c.xmin = domain.xmin;
  c.xmax = domain.xmax;
  switch (coords) {
    case CoordinateSystem::cartesian:
      break;
    case CoordinateSystem::cylindrical:
      c.boundary_lower = {Boundary::axis, Boundary::outflow, Boundary::periodic};
      c.boundary_upper = {Boundary::outflow, Boundary::outflow, Boundary::periodic};
      break;
    case CoordinateSystem::spherical:
      c.boundary_lower = {Boundary::origin, Boundary::axis, Boundary::periodic};
      c.boundary_upper = {Boundary::outflow, Boundary::axis, Boundary::periodic};
      break;
  }
  return c;
}

void fill_curl_of_random_potential(AmrGrid& grid, const FaceField& f, int finest, std::uint64_t seed) {
  const GridConfig& c = grid.config();
  Potential pot{c, finest, seed, {}};
  for (std::size_t d = 0; d < 3; ++d) pot.cells_finest[d] = static_cast<int>(d) < c.dimension ? c.ncells[d] << finest : 1;
  for (Block* b : grid.local_blocks())
    for (int d = 0; d < c.dimension; ++d) {
      Field B = b->field(f.group[d], 0);
      const int top[3] = {b->n[0] + (d == 0), b->n[1] + (d == 1), b->n[2] + (d == 2 && c.dimension == 3)};
      for (int k = 0; k < top[2]; ++k)
        for (int j = 0; j < top[1]; ++j)
          for (int i = 0; i < top[0]; ++i) {
            const std::array<std::int64_t, 3> p{b->index[0] * b->n[0] + i, b->index[1] * b->n[1] + j,
                                                b->index[2] * b->n[2] + k};
            const double area = b->face_area(d, i, j, k);
            B(i, j, k) = area > 0 ? pot.flux(b->level, d, p) / area : 0.0;
          }
    }
}

double cell_outflow(Block& b, const FaceField& f, int i, int j, int k, double* magnitude) {
  double s = 0, m = 0;
  const int dim = b.n[2] > 1 || b.ng[2] > 0 ? 3 : 2;
  for (int d = 0; d < dim; ++d) {
    const Field B = b.field(f.group[d], 0);
    const int ip = i + (d == 0), jp = j + (d == 1), kp = k + (d == 2);
    const double up = b.face_area(d, ip, jp, kp) * B(ip, jp, kp), lo = b.face_area(d, i, j, k) * B(i, j, k);
    s += up - lo;
    m += std::abs(up) + std::abs(lo);
  }
  if (magnitude) *magnitude = m;
  return s;
}

DivergenceStats divergence_stats(AmrGrid& grid, const FaceField& f) {
  DivergenceStats st;
  double bmax = 0, div_dx = 0;
  for (Block* b : grid.local_blocks()) {
    for (int d = 0; d < grid.dimension(); ++d) {
      const Field B = b->field(f.group[d], 0);
      for (int k = 0; k < b->n[2] + (d == 2); ++k)
        for (int j = 0; j < b->n[1] + (d == 1); ++j)
          for (int i = 0; i < b->n[0] + (d == 0); ++i)
            if (b->face_area(d, i, j, k) > 0) bmax = std::max(bmax, std::abs(B(i, j, k)));
    }
    for_interior(*b, [&](int i, int j, int k) {
      double m = 0;
      const double out = cell_outflow(*b, f, i, j, k, &m);
      if (m > 0) st.relative = std::max(st.relative, std::abs(out) / m);
      div_dx = std::max(div_dx, std::abs(out) / b->cell_volume(i, j, k) * b->dx[0]);
    });
  }
  st.scaled = bmax > 0 ? div_dx / bmax : 0;
  return st;
}

double shared_face_mismatch(AmrGrid& grid, const FaceField& f) {
  std::map<std::tuple<int, std::int64_t, std::int64_t, std::int64_t>, Block*> at;
  for (Block* b : grid.local_blocks()) at[{b->level, b->index[0], b->index[1], b->index[2]}] = b;
  double worst = 0, bmax = 0;
  for (Block* b : grid.local_blocks())
    for (int d = 0; d < grid.dimension(); ++d) {
      const Field B = b->field(f.group[d], 0);
      for_interior(*b, [&](int i, int j, int k) { bmax = std::max(bmax, std::abs(B(i, j, k))); });
      std::array<std::int64_t, 3> K = b->index;
      K[static_cast<std::size_t>(d)] += 1;
      auto it = at.find({b->level, K[0], K[1], K[2]});
      if (it == at.end()) continue;
      const Field N = it->second->field(f.group[d], 0);
      for_interior(*b, [&](int i, int j, int k) {
        int p[3] = {i, j, k}, q[3] = {i, j, k};
        if (p[d] != 0) return;
        p[d] = b->n[static_cast<std::size_t>(d)];
        worst = std::max(worst, std::abs(B(p[0], p[1], p[2]) - N(q[0], q[1], q[2])));
      });
    }
  return bmax > 0 ? worst / bmax : 0;
}

EdgeSetup::EdgeSetup() : f(make_face_field()) {
  const Centering cs[3] = {Centering::edge_x, Centering::edge_y, Centering::edge_z};
  const char* names[3] = {"Ex", "Ey", "Ez"};
  for (int a = 0; a < 3; ++a) {
    VariableGroupSpec g;
    g.thorn = "Test";
    g.name = names[a];
    g.centering = cs[a];
    g.components = expand_tensor(TensorKind::scalar, names[a]);
    edge[a] = f.vars.add(std::move(g));
  }
}

void fill_emf(AmrGrid& grid, const EdgeSetup& s) {
  const int dim = grid.dimension();
  for (Block* b : grid.local_blocks())
    for (int a = 0; a < 3; ++a) {
      const Field E = b->field(s.edge[a], 0);
      const auto st = staggering(static_cast<Centering>(static_cast<int>(Centering::edge_x) + a));
      int top[3];
      for (int e = 0; e < 3; ++e) top[e] = b->n[static_cast<std::size_t>(e)] + (e < dim ? st[static_cast<std::size_t>(e)] : 0);
      for (int k = 0; k < top[2]; ++k)
        for (int j = 0; j < top[1]; ++j)
          for (int i = 0; i < top[0]; ++i) {
            const int p[3] = {i, j, k};
            Point3 x{};
            for (int e = 0; e < 3; ++e)
              x[static_cast<std::size_t>(e)] = st[static_cast<std::size_t>(e)] ? b->face_coordinate(e, p[e]) : b->x(e, p[e]);
            // 2D: the potential runs along the unused direction only.
            // Each block's own variant (blocks near refinement boundaries see different ghosts).
            E(i, j, k) = dim == 2 && a < 2 ? 0.0 : emf(grid.coordinates(), b->level, a, x, 1 + 1e-3 * static_cast<double>(b->gid));
          }
    }
}

namespace {

// Calls fn(a, E, i, j, k, global) for every interior edge of group a of block b; `global` is the
// edge's index on its level, wrapped across periodic directions.
template <class Fn>
void for_each_edge(AmrGrid& grid, const EdgeSetup& s, Block& b, Fn&& fn) {
  const GridConfig& c = grid.config();
  for (int a = 0; a < 3; ++a) {
    const Field E = b.field(s.edge[a], 0);
    const auto st = staggering(static_cast<Centering>(static_cast<int>(Centering::edge_x) + a));
    int top[3];
    for (int e = 0; e < 3; ++e) top[e] = b.n[static_cast<std::size_t>(e)] + (e < c.dimension ? st[static_cast<std::size_t>(e)] : 0);
    for (int k = 0; k < top[2]; ++k)
      for (int j = 0; j < top[1]; ++j)
        for (int i = 0; i < top[0]; ++i) {
          const int p[3] = {i, j, k};
          std::array<std::int64_t, 3> g{};
          for (std::size_t e = 0; e < 3; ++e) {
            g[e] = b.index[e] * b.n[e] + p[e];
            const std::int64_t cells = static_cast<std::int64_t>(c.ncells[e]) << b.level;
            if (static_cast<int>(e) < c.dimension && c.boundary_lower[e] == Boundary::periodic) g[e] %= cells;
          }
          fn(a, E, i, j, k, g);
        }
  }
}

}  // namespace

void fill_distinct_edges(AmrGrid& grid, const EdgeSetup& s) {
  for (Block* b : grid.local_blocks())
    for_each_edge(grid, s, *b, [&](int a, const Field& E, int i, int j, int k, const std::array<std::int64_t, 3>& g) {
      E(i, j, k) = (1 + a + 0.1 * b->level + 0.01 * static_cast<double>(g[0]) + 1e-4 * static_cast<double>(g[1]) +
                    1e-6 * static_cast<double>(g[2])) *
                   (1 + 1e-3 * static_cast<double>(b->gid));
    });
}

double edge_copy_mismatch(AmrGrid& grid, const EdgeSetup& s) {
  std::map<std::tuple<int, int, std::int64_t, std::int64_t, std::int64_t>, double> first;
  double worst = 0;
  for (Block* b : grid.local_blocks())
    for_each_edge(grid, s, *b, [&](int a, const Field& E, int i, int j, int k, const std::array<std::int64_t, 3>& g) {
      const auto [it, fresh] = first.try_emplace({a, b->level, g[0], g[1], g[2]}, E(i, j, k));
      if (!fresh) worst = std::max(worst, std::abs(E(i, j, k) - it->second));
    });
  return worst;
}

void ct_update(AmrGrid& grid, const EdgeSetup& s, double dt) {
  const int dim = grid.dimension();
  for (Block* b : grid.local_blocks()) {
    auto length = [&](int a) { return a < dim ? b->dx[static_cast<std::size_t>(a)] : 1.0; };
    auto edge = [&](int a, int i, int j, int k) {
      if (dim == 2 && a < 2) return 0.0;
      return b->field(s.edge[a], 0)(i, j, k) * length(a);
    };
    for (int d = 0; d < dim; ++d) {
      const int a = (d + 1) % 3, c = (d + 2) % 3;
      const Field B = b->field(s.f.group[d], 0);
      for (int k = 0; k < b->n[2] + (d == 2); ++k)
        for (int j = 0; j < b->n[1] + (d == 1); ++j)
          for (int i = 0; i < b->n[0] + (d == 0); ++i) {
            auto step = [&](int e, int p[3]) { if (e < dim) p[e] += 1; };
            int pa[3] = {i, j, k}, pc[3] = {i, j, k};
            step(a, pa);
            step(c, pc);
            const double circ = edge(a, i, j, k) + edge(c, pa[0], pa[1], pa[2]) - edge(a, pc[0], pc[1], pc[2]) -
                                edge(c, i, j, k);
            const double area = b->face_area(d, i, j, k);
            if (area > 0) B(i, j, k) = (area * B(i, j, k) - dt * circ) / area;
          }
    }
  }
}

}  // namespace remnant::grid::test
