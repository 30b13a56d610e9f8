#pragma once
// The Remnant grid that receives the data, seen from the 3D Cartesian source: its coordinates, its
// extent, and its mirror symmetries (a reflecting lower face at x^d = 0, the cylindrical z = 0, the
// spherical equator). The fundamental domain is the grid itself; the covered region is the grid
// unfolded by its mirrors (what its integrals stand for, twice or eight times over).
#include <array>
#include <string>

#include "remnant/coordinates.hpp"

namespace remnant {
class Parameters;
}

namespace remnant::handoff {

struct TargetDomain {
  CoordinateSystem coordinates = CoordinateSystem::cartesian;
  int dimension = 3;
  Point3 lo{0, 0, 0}, hi{1, 1, 1};
  std::array<bool, 3> mirror{false, false, false};  // Cartesian axes mirrored (x, y, z)

  static TargetDomain from_parameters(const Parameters& p);
  // Grid coordinates of a Cartesian point (R, z, phi in [0, 2 pi) / r, theta, phi).
  Point3 coordinates_of(const Point3& X) const;
  // The image of X under the grid's mirrors that lies on the grid's side.
  Point3 fold(const Point3& X) const;
  // Inside the grid's extent (closed box in the grid's used directions).
  bool contains(const Point3& X) const;
  // The fraction of the cube of side h about X inside the grid: exact for faces of constant
  // Cartesian coordinate (x, y, z of a Cartesian grid, z of a cylindrical one), by position otherwise.
  double fraction_inside(const Point3& X, double h) const;
  // True for 2D curvilinear grids: each cell is the average over phi.
  bool averages_over_phi() const { return dimension == 2 && coordinates != CoordinateSystem::cartesian; }
  std::string describe() const;
};

}  // namespace remnant::handoff
