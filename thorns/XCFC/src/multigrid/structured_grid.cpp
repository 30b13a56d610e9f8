#include "XCFC/multigrid/structured_grid.hpp"

#include <numbers>

namespace remnant::xcfc {

Point3 GridShape::point(int i, int j, int k) const {
  Point3 x{centre(0, i), centre(1, j), centre(2, k)};
  if (!used(1)) x[1] = coordinates == CoordinateSystem::spherical ? 0.5 * std::numbers::pi : 0.0;
  if (!used(2)) x[2] = 0.0;
  return x;
}

}  // namespace remnant::xcfc
