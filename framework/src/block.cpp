// Storage of one mesh block: per variable group, ncomp contiguous arrays (component-major), each
// with ghost zones on both sides, i fastest.
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
  for (const auto& group : vars.groups()) {
    const auto e = extent(group.centering);
    const auto points = static_cast<std::size_t>(e[0]) * static_cast<std::size_t>(e[1]) *
                        static_cast<std::size_t>(e[2]);
    points_.push_back(points);
    data_.emplace_back(points * static_cast<std::size_t>(group.ncomp()), 0.0);
  }
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

Field Block::field(int group, int comp) {
  const auto& spec = vars_->group(group);
  if (comp < 0 || comp >= spec.ncomp())
    throw std::out_of_range("Block::field: component " + std::to_string(comp) + " of group '" +
                            spec.full_name() + "', which has " + std::to_string(spec.ncomp()));
  const auto e = extent(spec.centering);
  Field f;
  f.sj = e[0];
  f.sk = static_cast<std::ptrdiff_t>(e[0]) * e[1];
  f.origin = data(group) + static_cast<std::ptrdiff_t>(comp) *
                               static_cast<std::ptrdiff_t>(points_per_component(group)) +
             ng[0] + ng[1] * f.sj + ng[2] * f.sk;
  return f;
}

double Block::cell_volume() const {
  double v = 1.0;
  for (int d = 0; d < 3; ++d)
    if (direction_used(n, ng, d)) v *= dx[static_cast<std::size_t>(d)];
  return v;
}

const char* to_string(CoordinateSystem c) {
  switch (c) {
    case CoordinateSystem::cartesian: return "cartesian";
    case CoordinateSystem::cylindrical: return "cylindrical";
    case CoordinateSystem::spherical: return "spherical";
  }
  return "?";
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
