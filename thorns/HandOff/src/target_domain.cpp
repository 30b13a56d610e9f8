#include "HandOff/target_domain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "remnant/error.hpp"
#include "remnant/parameters.hpp"

namespace remnant::handoff {
namespace {
// Directions whose faces are planes of constant Cartesian coordinate, and which coordinate.
int cartesian_axis(CoordinateSystem c, int d) {
  if (c == CoordinateSystem::cartesian) return d;
  if (c == CoordinateSystem::cylindrical && d == 1) return 2;
  return -1;
}
}  // namespace

TargetDomain TargetDomain::from_parameters(const Parameters& p) {
  TargetDomain t;
  const auto& c = p.get<std::string>("Grid", "coordinates");
  t.coordinates = c == "cylindrical" ? CoordinateSystem::cylindrical
                  : c == "spherical" ? CoordinateSystem::spherical
                                     : CoordinateSystem::cartesian;
  t.dimension = static_cast<int>(p.get<std::int64_t>("Grid", "dimension"));
  const auto& lo = p.get<std::vector<double>>("Grid", "xmin");
  const auto& hi = p.get<std::vector<double>>("Grid", "xmax");
  for (std::size_t d = 0; d < 3; ++d) t.lo[d] = lo[d], t.hi[d] = hi[d];
  const bool curvilinear_2d = t.dimension == 2 && t.coordinates != CoordinateSystem::cartesian;
  if (!(t.dimension == 3 || curvilinear_2d))
    throw InputError(p.origin("Grid", "dimension"),
                     "HandOff fills 3D grids (any coordinates) and 2D cylindrical or spherical grids (averaged over phi); "
                     "this grid is " + std::to_string(t.dimension) + "D " + c);
  const auto& bl = p.get<std::vector<std::string>>("Grid", "boundary_lower");
  const auto& bu = p.get<std::vector<std::string>>("Grid", "boundary_upper");
  if (t.coordinates == CoordinateSystem::cartesian) {
    for (std::size_t d = 0; d < 3; ++d) t.mirror[d] = bl[d] == "reflect" && t.lo[d] == 0;
  } else if (t.coordinates == CoordinateSystem::cylindrical) {
    t.mirror[2] = bl[1] == "reflect" && t.lo[1] == 0;
  } else {
    t.mirror[2] = bu[1] == "reflect" && std::abs(t.hi[1] - std::numbers::pi / 2) < 1e-12;
  }
  return t;
}

Point3 TargetDomain::coordinates_of(const Point3& X) const {
  const double R = std::hypot(X[0], X[1]);
  double phi = std::atan2(X[1], X[0]);
  if (phi < 0) phi += 2 * std::numbers::pi;
  switch (coordinates) {
    case CoordinateSystem::cartesian: return X;
    case CoordinateSystem::cylindrical: return {R, X[2], phi};
    case CoordinateSystem::spherical: {
      const double r = std::hypot(R, X[2]);
      return {r, r > 0 ? std::acos(std::clamp(X[2] / r, -1.0, 1.0)) : 0.0, phi};
    }
  }
  return X;
}

Point3 TargetDomain::fold(const Point3& X) const {
  Point3 Y = X;
  for (std::size_t a = 0; a < 3; ++a)
    if (mirror[a]) Y[a] = std::abs(Y[a]);
  return Y;
}

bool TargetDomain::contains(const Point3& X) const {
  const Point3 x = coordinates_of(X);
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    if (d >= dimension && coords::is_angle(coordinates, d)) continue;  // spans its whole range
    if (x[ud] < lo[ud] || x[ud] > hi[ud]) return false;
  }
  return true;
}

double TargetDomain::fraction_inside(const Point3& X, double h) const {
  const Point3 x = coordinates_of(X);
  double f = 1;
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    if (d >= dimension && coords::is_angle(coordinates, d)) continue;
    const int a = cartesian_axis(coordinates, d);
    // The spherical equator theta = pi/2 is the plane z = 0.
    const bool equator_hi = coordinates == CoordinateSystem::spherical && d == 1 && std::abs(hi[1] - std::numbers::pi / 2) < 1e-12;
    const bool equator_lo = coordinates == CoordinateSystem::spherical && d == 1 && std::abs(lo[1] - std::numbers::pi / 2) < 1e-12;
    if (equator_hi || equator_lo) {  // overlap of [z - h/2, z + h/2] with z >= 0 (or z <= 0)
      const double z = X[2];
      const double overlap = equator_hi ? (z + h / 2) - std::max(z - h / 2, 0.0) : std::min(z + h / 2, 0.0) - (z - h / 2);
      f *= std::clamp(overlap / h, 0.0, 1.0);
    } else if (a >= 0) {
      const double c = X[static_cast<std::size_t>(a)];
      const double overlap = std::min(c + h / 2, hi[ud]) - std::max(c - h / 2, lo[ud]);
      f *= std::clamp(overlap / h, 0.0, 1.0);
    } else if (x[ud] < lo[ud] || x[ud] > hi[ud]) {
      return 0;
    }
  }
  return f;
}

std::string TargetDomain::describe() const {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%dD %s [%g, %g] x [%g, %g] x [%g, %g]%s%s%s", dimension, to_string(coordinates), lo[0],
                hi[0], lo[1], hi[1], lo[2], hi[2], mirror[0] ? ", mirror x" : "", mirror[1] ? ", mirror y" : "",
                mirror[2] ? ", mirror z" : "");
  return buf;
}

}  // namespace remnant::handoff
