#pragma once
// The 2D spherical grid of the xCFC solver tests: r in [0, rmax] from the origin, theta in
// [0, pi/2] from the axis to the equatorial plane (reflect), one phi cell; nr x ntheta cells.
#include <numbers>

#include "XCFC/multigrid/multigrid.hpp"

namespace remnant::xcfc::test {

inline GridShape spherical_octant_2d(int nr, int ntheta, double rmax) {
  GridShape s;
  s.coordinates = CoordinateSystem::spherical;
  s.dimension = 2;
  s.n = {nr, ntheta, 1};
  s.dx = {rmax / nr, std::numbers::pi / 2 / ntheta, 2 * std::numbers::pi};
  s.boundary = {{{Boundary::origin, Boundary::outer}, {Boundary::axis, Boundary::reflect}, {Boundary::outer, Boundary::outer}}};
  return s;
}

}  // namespace remnant::xcfc::test
