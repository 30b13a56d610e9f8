#pragma once
// The two stellar field laws of issue 15 (pointwise; see README.md).
//
// Poloidal (the vector potential of e.g. Cheong et al.'s magnetised stars):
//   A_phi = A_b varpi^2 max(p - p_cut, 0)^n_s,   varpi the coordinate cylindrical radius.
// Toroidal (Kiuchi & Yoshida 2008, the paper's magnetized-DRNS, XNS's alpha B_phi = K_m G^m):
//   B := sqrt(B_i B^i) = K_m (alpha^2 varpi^2 rho h)^m / (alpha varpi)  for rho > rho_cut, else 0,
//   varpi = psi^2 R the generalised cylindrical radius, R = r sin(theta) the coordinate one.
// The field is along phi: B^phi = B / sqrt(g_phiphi) = B / (psi^2 R), so the face value
// psi^6 B^phi = psi^4 B / R = K_m psi^2 (alpha^2 psi^4 rho h)^m R^(2m-2) / alpha (regular on the
// axis for m >= 1; m = 1: K_m alpha psi^6 rho h).
#include <algorithm>
#include <cmath>

namespace remnant::seed {

struct PoloidalLaw {
  double A_b = 1.0, p_cut = 0.0, n_s = 2.0;
  double a_phi(double varpi, double press) const {
    const double excess = std::max(press - p_cut, 0.0);
    return excess > 0.0 ? A_b * varpi * varpi * std::pow(excess, n_s) : 0.0;
  }
};

struct ToroidalLaw {
  double K_m = 3.0, m = 1.0, rho_cut = 1e-9;
  // psi^6 B^phi (coordinate component, densitised) at coordinate cylindrical radius R.
  double densitised_bphi(double R, double alpha, double psi, double rho, double h) const {
    if (!(rho > rho_cut)) return 0.0;
    const double psi2 = psi * psi;
    return K_m * psi2 / alpha * std::pow(alpha * alpha * psi2 * psi2 * rho * h, m) * std::pow(std::abs(R), 2.0 * m - 2.0);
  }
  // The paper's B = sqrt(B_i B^i), for checks.
  double magnitude(double R, double alpha, double psi, double rho, double h) const {
    if (!(rho > rho_cut) || R == 0.0) return 0.0;
    const double varpi = psi * psi * std::abs(R);
    return K_m * std::pow(alpha * alpha * varpi * varpi * rho * h, m) / (alpha * varpi);
  }
};

}  // namespace remnant::seed
