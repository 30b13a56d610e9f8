#pragma once
// The advected bump, the velocity field and the exact solution in any coordinate system.
#include <array>
#include <string>

#include "remnant/coordinates.hpp"

namespace remnant::advection {

enum class VelocityKind { cartesian, rotation, radial };

struct Setup {
  CoordinateSystem coords = CoordinateSystem::cartesian;
  VelocityKind kind = VelocityKind::cartesian;
  Point3 velocity{1, 0, 0};
  double omega = 1, radial_speed = 0.5;
  Point3 centre{0, 0, 0};
  double width = 0.3, amplitude = 1, background = 0;
};

// Coordinate components v^i at the point x.
Point3 velocity(const Setup& s, const Point3& x);
// The solution at time t at the point x.
double exact(const Setup& s, double t, const Point3& x);
// The bump centre (Cartesian; radial: the coordinate in the first entry) at time t.
Point3 centre_at(const Setup& s, double t);

}  // namespace remnant::advection
