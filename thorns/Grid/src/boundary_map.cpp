#include "boundary_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "remnant/error.hpp"

namespace remnant::grid {

BoundaryMaps::BoundaryMaps(const GridConfig& config) : config_(config) {
  faces_.coordinates = config.coordinates;
  faces_.dimension = config.dimension;
  for (std::size_t d = 0; d < 3; ++d) faces_.boundary[d] = {config.boundary_lower[d], config.boundary_upper[d]};
  faces_.axial_reflection = config.axial_reflection;
  if (config.coordinates == CoordinateSystem::spherical && config.dimension >= 2) {
    const double dtheta = (config.xmax[1] - config.xmin[1]) / static_cast<double>(config.ncells[1]);
    theta_cells_to_pi_ = std::llround(std::numbers::pi / dtheta);
  }
}

Range BoundaryMaps::cells_on_level(int level) const {
  Range n{};
  for (std::size_t d = 0; d < 3; ++d)
    n[d] = static_cast<int>(d) < config_.dimension ? config_.ncells[d] << level : 1;
  return n;
}

std::optional<IndexMap> BoundaryMaps::image(int level, const std::array<int, 3>& stagger, const GlobalBox& box) const {
  try {
    return faces_.image(cells_on_level(level), theta_cells_to_pi_ << level, stagger, box);
  } catch (const std::logic_error& e) {
    throw RunError(std::string("Grid: internal error: ") + e.what());
  }
}

}  // namespace remnant::grid
