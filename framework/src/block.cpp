// Storage of one mesh block: per variable group, ncomp contiguous arrays (component-major), each
// with ghost zones on both sides, i fastest.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "remnant/grid.hpp"

namespace remnant {

namespace {
// A direction is in use unless it has a single cell and no ghosts (the size-1 directions of 1D/2D).
bool direction_used(const std::array<int, 3>& n, const std::array<int, 3>& ng, int d) {
  const auto i = static_cast<std::size_t>(d);
  return ng[i] > 0 || n[i] > 1;
}
}  // namespace

Block::Block(std::int64_t gid_, int level_, std::array<std::int64_t, 3> index_,
             std::array<int, 3> n_, std::array<int, 3> ng_, std::array<double, 3> lo_,
             std::array<double, 3> dx_, const VariableRegistry& vars)
    : gid(gid_), level(level_), index(index_), n(n_), ng(ng_), lo(lo_), dx(dx_), vars_(&vars) {
  data_.reserve(static_cast<std::size_t>(vars.size()));
  points_.reserve(static_cast<std::size_t>(vars.size()));
  ghosts_.reserve(static_cast<std::size_t>(vars.size()));
  for (const auto& group : vars.groups()) {
    std::array<int, 3> g = ng;
    if (group.ghosts >= 0)
      for (auto& layers : g) layers = std::min(layers, group.ghosts);
    ghosts_.push_back(g);
    const auto e = group_extent(group.id);
    const auto points = static_cast<std::size_t>(e[0]) * static_cast<std::size_t>(e[1]) *
                        static_cast<std::size_t>(e[2]);
    points_.push_back(points);
    data_.emplace_back(points * static_cast<std::size_t>(group.ncomp()), 0.0);
  }
  std::array<double, 3> domain_lo{};
  for (std::size_t d = 0; d < 3; ++d) domain_lo[d] = lo[d] - static_cast<double>(index[d] * n[d]) * dx[d];
  set_geometry(CoordinateSystem::cartesian, domain_lo);
}

void Block::set_geometry(CoordinateSystem c, const std::array<double, 3>& domain_lo) {
  coordinates = c;
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    DirectionGeometry& g = geo_[ud];
    const int cells = n[ud] + 2 * ng[ud];
    g.face.resize(static_cast<std::size_t>(cells + 1));
    g.centroid.resize(static_cast<std::size_t>(cells + 1));
    g.weight.resize(static_cast<std::size_t>(cells + 1));
    g.face_factor.resize(static_cast<std::size_t>(cells + 1));
    const bool used = direction_used(n, ng, d);
    const std::int64_t first = index[ud] * n[ud] - ng[ud];
    for (int p = 0; p <= cells; ++p) {
      // The lower domain face is domain_lo exactly; the upper face of an unused direction is lo + dx.
      const std::int64_t global = first + p;
      g.face[static_cast<std::size_t>(p)] =
          global == 0 ? domain_lo[ud] : domain_lo[ud] + static_cast<double>(global) * dx[ud];
    }
    for (int p = 0; p <= cells; ++p) {
      const double a = g.face[static_cast<std::size_t>(p)];
      const double b = p < cells ? g.face[static_cast<std::size_t>(p + 1)] : a + dx[ud];
      double factor = coords::volume_factor(c, d, a);
      // Axes and the origin have exactly zero area (sin(pi) is not 0 in floating point).
      if (coords::is_angle(c, d) && d == 1 && std::abs(a - std::numbers::pi) < 1e-12) factor = 0.0;
      g.face_factor[static_cast<std::size_t>(p)] = factor;
      g.centroid[static_cast<std::size_t>(p)] = coords::centroid(c, d, a, b);
      // Constant factors (Cartesian directions, z, phi) weigh every cell by exactly dx.
      const bool constant_factor = coords::volume_factor(c, d, 0.3) == 1.0 && coords::volume_factor(c, d, 0.7) == 1.0;
      double w = 1.0;
      if (used || coords::is_angle(c, d)) w = constant_factor ? dx[ud] : coords::volume_factor_integral(c, d, a, b);
      g.weight[static_cast<std::size_t>(p)] = w;
    }
  }
}

double Block::face_area(int d, int i, int j, int k) const {
  const int idx[3] = {i, j, k};
  double a = 1.0;
  for (int e = 0; e < 3; ++e) {
    const auto ue = static_cast<std::size_t>(e);
    const auto p = static_cast<std::size_t>(idx[e] + ng[ue]);
    a *= e == d ? geo_[ue].face_factor[p] : geo_[ue].weight[p];
  }
  return a;
}

double Block::sqrt_f(int i, int j, int k) const {
  return coords::sqrt_det_metric(coordinates, {centroid(0, i), centroid(1, j), centroid(2, k)});
}

std::array<int, 3> Block::extent(Centering c) const {
  const auto stagger = staggering(c);
  std::array<int, 3> e{};
  for (int d = 0; d < 3; ++d) {
    const auto i = static_cast<std::size_t>(d);
    // Staggered points add the upper face only where the direction exists.
    e[i] = n[i] + 2 * ng[i] + (direction_used(n, ng, d) ? stagger[i] : 0);
  }
  return e;
}

std::array<int, 3> Block::group_extent(int group) const {
  const auto stagger = staggering(vars_->group(group).centering);
  const auto& g = ghosts(group);
  std::array<int, 3> e{};
  for (int d = 0; d < 3; ++d) {
    const auto i = static_cast<std::size_t>(d);
    e[i] = n[i] + 2 * g[i] + (direction_used(n, ng, d) ? stagger[i] : 0);
  }
  return e;
}

Field Block::field(int group, int comp) {
  const auto& spec = vars_->group(group);
  if (comp < 0 || comp >= spec.ncomp())
    throw std::out_of_range("Block::field: component " + std::to_string(comp) + " of group '" +
                            spec.full_name() + "', which has " + std::to_string(spec.ncomp()));
  const auto e = group_extent(group);
  const auto& g = ghosts(group);
  Field f;
  f.sj = e[0];
  f.sk = static_cast<std::ptrdiff_t>(e[0]) * e[1];
  f.origin = data(group) + static_cast<std::ptrdiff_t>(comp) *
                               static_cast<std::ptrdiff_t>(points_per_component(group)) +
             g[0] + g[1] * f.sj + g[2] * f.sk;
  return f;
}

double Block::cell_volume() const {
  double v = 1.0;
  for (int d = 0; d < 3; ++d)
    if (direction_used(n, ng, d)) v *= dx[static_cast<std::size_t>(d)];
  return v;
}

const char* to_string(ReductionKind k) {
  switch (k) {
    case ReductionKind::minimum: return "minimum";
    case ReductionKind::maximum: return "maximum";
    case ReductionKind::sum: return "sum";
    case ReductionKind::volume_integral: return "volume_integral";
    case ReductionKind::norm1: return "norm1";
    case ReductionKind::norm2: return "norm2";
  }
  return "?";
}

}  // namespace remnant
