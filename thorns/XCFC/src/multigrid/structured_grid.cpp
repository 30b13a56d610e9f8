#include "XCFC/multigrid/structured_grid.hpp"

#include <numbers>

namespace remnant::xcfc {

Point3 GridShape::point(int i, int j, int k) const {
  Point3 x{centre(0, i), centre(1, j), centre(2, k)};
  if (!used(1)) x[1] = coordinates == CoordinateSystem::spherical ? 0.5 * std::numbers::pi : 0.0;
  if (!used(2)) x[2] = 0.0;
  return x;
}

bool GridShape::origin_flips_theta() const {
  return !(dimension >= 2 && boundary[1][1] == Boundary::reflect);
}

bool GridShape::turns_phi() const {
  if (dimension < 3 || coordinates == CoordinateSystem::cartesian) return false;
  for (int d = 0; d < 2; ++d)
    for (const Boundary b : boundary[d])
      if (b == Boundary::axis || b == Boundary::origin) return true;
  return false;
}

std::array<long long, 3> GridShape::image(std::array<long long, 3> I, int d, int side) const {
  const long long m = n[d];
  const Boundary kind = boundary[d][side];
  if (kind == Boundary::periodic) {
    I[d] = ((I[d] % m) + m) % m;
    return I;
  }
  I[d] = side == 0 ? -1 - I[d] : 2 * m - 1 - I[d];
  if (kind == Boundary::origin && used(1) && origin_flips_theta()) I[1] = n[1] - 1 - I[1];
  if ((kind == Boundary::axis || kind == Boundary::origin) && turns_phi()) I[2] = ((I[2] + n[2] / 2) % n[2] + n[2]) % n[2];
  return I;
}

}  // namespace remnant::xcfc
