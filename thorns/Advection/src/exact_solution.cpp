#include "exact_solution.hpp"

#include <cmath>

namespace remnant::advection {

namespace {
double bump(const Setup& s, double d) {
  if (d >= s.width) return s.background;
  const double q = 1 - (d / s.width) * (d / s.width);
  return s.background + s.amplitude * q * q * q * q;
}
}  // namespace

Point3 velocity(const Setup& s, const Point3& x) {
  switch (s.kind) {
    case VelocityKind::cartesian: return coords::vector_from_cartesian(s.coords, x, s.velocity);
    case VelocityKind::rotation:
      if (s.coords == CoordinateSystem::cartesian) return {-s.omega * x[1], s.omega * x[0], 0};
      return {0, 0, s.omega};
    case VelocityKind::radial: return {s.radial_speed, 0, 0};
  }
  return {0, 0, 0};
}

Point3 centre_at(const Setup& s, double t) {
  switch (s.kind) {
    case VelocityKind::cartesian:
      return {s.centre[0] + s.velocity[0] * t, s.centre[1] + s.velocity[1] * t, s.centre[2] + s.velocity[2] * t};
    case VelocityKind::rotation: {
      const double c = std::cos(s.omega * t), sn = std::sin(s.omega * t);
      return {c * s.centre[0] - sn * s.centre[1], sn * s.centre[0] + c * s.centre[1], s.centre[2]};
    }
    case VelocityKind::radial: return {s.centre[0] + s.radial_speed * t, 0, 0};
  }
  return s.centre;
}

double exact(const Setup& s, double t, const Point3& x) {
  if (s.kind == VelocityKind::radial) {
    // d_t (r^k u) + d_r (r^k u c) = 0: r^k u is carried along r - c t.
    const double k = s.coords == CoordinateSystem::spherical ? 2 : s.coords == CoordinateSystem::cylindrical ? 1 : 0;
    const double r0 = x[0] - s.radial_speed * t;
    const double u0 = bump(s, std::abs(r0 - s.centre[0]));
    if (u0 == s.background) return s.background;
    return s.background + (u0 - s.background) * std::pow(r0 / x[0], k);
  }
  const Point3 X = coords::to_cartesian(s.coords, x);
  const Point3 c = centre_at(s, t);
  return bump(s, std::hypot(X[0] - c[0], X[1] - c[1], X[2] - c[2]));
}

}  // namespace remnant::advection
