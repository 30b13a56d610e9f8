#include "curvilinear.hpp"

#include <cmath>

namespace remnant::io {

int cartesian_components(CoordinateSystem c, int dimension) {
  (void)c;
  return dimension;
}

std::array<double, 3> to_cartesian(CoordinateSystem c, int dimension, const std::array<double, 3>& q) {
  switch (c) {
    case CoordinateSystem::cartesian:
      return q;
    case CoordinateSystem::cylindrical:  // (R, z, phi)
      if (dimension < 3) return {q[0], dimension > 1 ? q[1] : 0.0, 0.0};
      return {q[0] * std::cos(q[2]), q[0] * std::sin(q[2]), q[1]};
    case CoordinateSystem::spherical:  // (r, theta, phi)
      if (dimension == 1) return {q[0], 0.0, 0.0};
      if (dimension == 2) return {q[0] * std::sin(q[1]), q[0] * std::cos(q[1]), 0.0};
      return {q[0] * std::sin(q[1]) * std::cos(q[2]), q[0] * std::sin(q[1]) * std::sin(q[2]), q[0] * std::cos(q[1])};
  }
  return q;
}

}  // namespace remnant::io
