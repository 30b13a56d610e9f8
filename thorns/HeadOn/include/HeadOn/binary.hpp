#pragma once
// Two identical TOV stars on the z axis, centres at z = -d/2 (star 0) and z = +d/2 (star 1), as
// the paper superposes them (section "Head-on collision of two neutron stars", after Tootle et al.):
//   X_bin(x) = Xi + kappa_0 (X_0(x - x_c0) - Xi) + kappa_1 (X_1(x - x_c1) - Xi),
//   kappa_i = exp[-(r_i / (d/2))^4],
// with Xi the asymptotic value (psi = alpha = 1, beta = 0). The matter of each star is taken where
// it is (the stars must not overlap). Everything here is in Cartesian coordinates.
#include <array>

#include "TOV/tov_solver.hpp"

namespace remnant::headon {

// kappa = exp[-(r / (d/2))^4]: 1 at the centre, e^-1 at r = d/2, 1.1e-7 at r = d.
double decay_weight(double r, double separation);

struct BinaryPoint {
  double psi = 1, alpha = 1;
  int star = -1;          // the star whose matter is here: 0 (z < 0), 1 (z > 0), -1 none
  tov::TovPoint matter;   // that star's cold state (rho = 0 outside both stars)
  double vz = 0;          // coordinate velocity v^z of the matter (towards the other star)
  double psi_isolated = 1;  // psi of the isolated star at this point (1 outside both stars)
};

class Binary {
 public:
  // infall: |v^z| of each star towards the other.
  Binary(const tov::TovStar& star, double separation, double infall = 0.0);
  double separation() const { return d_; }
  std::array<double, 2> centre_z() const { return {-0.5 * d_, 0.5 * d_}; }
  BinaryPoint at(const std::array<double, 3>& x) const;  // Cartesian point

 private:
  const tov::TovStar& star_;
  double d_, v_;
};

}  // namespace remnant::headon
