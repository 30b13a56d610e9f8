#include "HeadOn/binary.hpp"

#include <cmath>

namespace remnant::headon {

double decay_weight(double r, double separation) {
  const double q = r / (0.5 * separation), q2 = q * q;
  return std::exp(-q2 * q2);
}

Binary::Binary(const tov::TovStar& star, double separation, double infall) : star_(star), d_(separation), v_(infall) {}

BinaryPoint Binary::at(const std::array<double, 3>& x) const {
  BinaryPoint b;
  const auto zc = centre_z();
  const double rho2 = x[0] * x[0] + x[1] * x[1];
  double psi = 1, alpha = 1;
  for (int s = 0; s < 2; ++s) {
    const double dz = x[2] - zc[static_cast<std::size_t>(s)];
    const double r = std::sqrt(rho2 + dz * dz);
    const tov::TovPoint p = star_.at(r);
    const double kappa = decay_weight(r, d_);
    psi += kappa * (p.psi - 1);
    alpha += kappa * (p.alpha - 1);
    if (p.inside && p.rho > 0) {
      b.star = s;
      b.matter = p;
      b.psi_isolated = p.psi;
      b.vz = s == 0 ? v_ : -v_;  // star 0 (z < 0) falls towards +z
    }
  }
  b.psi = psi;
  b.alpha = alpha;
  return b;
}

}  // namespace remnant::headon
