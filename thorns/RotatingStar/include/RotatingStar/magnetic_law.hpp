#pragma once
// The purely toroidal magnetic field of a stationary axisymmetric star by the magnetic-polytrope law
// of Kiuchi & Yoshida 2008 (as XNS: Bucciantini & Del Zanna 2011, Pili et al. 2014, and the paper's
// magnetized-DRNS):
//   B := sqrt(B_i B^i) = K_m G^m / (alpha varpi),   G = alpha^2 varpi^2 rho h,
// with varpi = psi^2 r sin(theta) the generalised cylindrical radius (Heaviside-Lorentz units with
// sqrt(4 pi) absorbed, magnetic pressure B^2 / 2: XNS's convention, kGaussPerCodeB converts).
// The Lorentz force of a toroidal field is -(1 / (2 alpha^2 varpi^2)) d_i(alpha^2 varpi^2 B^2); with
// alpha varpi B = M(G) = K_m G^m, divided by rho h it is -(M M'(G) / G) d_i G, a gradient: the
// Euler equation integrates to the Bernoulli integral
//   ln h + ln alpha - ln W (+ the rotation law's term) + m K_m^2 G^(2m-1) / (2m-1) = const,
// exact for m > 1/2 (m >= 1 keeps B regular on the axis: B ~ varpi^(2m-1)). Since the comoving and
// Eulerian fields are parallel to v (E = -v x B = 0), b^2 = B^2 and the xCFC sources gain
//   E += B^2 / 2, S = S^i_i += B^2 / 2, S^phi_phi (orthonormal) -= B^2 / 2, S_i unchanged.
#include <algorithm>
#include <cmath>

#include "TOV/cold_slice.hpp"

namespace remnant::rotstar {

struct ToroidalField {
  double K_m = 0;  // 0: no field
  double m = 1;    // >= 1

  bool active() const { return K_m > 0; }
  // The Bernoulli term m K_m^2 G^(2m-1) / (2m-1).
  double bernoulli_term(double G) const {
    return G > 0 ? m * K_m * K_m * std::pow(G, 2 * m - 1) / (2 * m - 1) : 0.0;
  }
  // B = K_m G^m / (alpha varpi) with G = alpha^2 varpi^2 rho h, written without the 1/varpi so that
  // it is regular on the axis: K_m alpha^(2m-1) varpi^(2m-1) (rho h)^m.
  double magnitude(double alpha, double varpi, double rho_h) const {
    if (!(rho_h > 0) || varpi == 0) return 0.0;
    return K_m * std::pow(alpha * varpi, 2 * m - 1) * std::pow(rho_h, m);
  }
  // The coordinate component B^phi = B / varpi_coordinate-metric = B / (psi^2 r sin(theta)):
  // K_m alpha^(2m-1) psi^(4m-4) R^(2m-2) (rho h)^m with R = r sin(theta) (m = 1: K_m alpha rho h).
  double phi_component(double alpha, double psi, double R, double rho_h) const {
    if (!(rho_h > 0)) return 0.0;
    return K_m * std::pow(alpha, 2 * m - 1) * std::pow(psi, 4 * m - 4) * std::pow(std::abs(R), 2 * m - 2) * std::pow(rho_h, m);
  }
};

// The log-enthalpy H = ln h where the Bernoulli integral with the field gives
//   H + m K_m^2 G(H)^(2m-1) / (2m-1) = rhs,   G(H) = a2w2 rho(H) h(H),   a2w2 = alpha^2 varpi^2,
// (rhs > 0; the left side rises monotonically from 0 at H = 0, so the root in (0, rhs] is unique).
// Regula falsi (Illinois) on [0, rhs], to round-off in H. Without a field H = rhs.
inline double log_enthalpy_with_field(const tov::ColdSlice& slice, const ToroidalField& f, double rhs, double a2w2) {
  if (!f.active() || !(rhs > 0) || a2w2 <= 0) return rhs;
  auto residual = [&](double H) {
    const tov::ColdState s = slice.at(H);
    const double rho_h = s.rho > 0 ? s.rho + s.rho * s.eps + s.press : 0.0;
    return H + f.bernoulli_term(a2w2 * rho_h) - rhs;
  };
  double lo = 0, hi = rhs, f_lo = -rhs, f_hi = residual(hi);
  if (f_hi <= 0) return rhs;
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * rhs; ++it) {
    const double H = std::clamp((lo * f_hi - hi * f_lo) / (f_hi - f_lo), lo, hi);
    const double fH = residual(H);
    if (std::abs(fH) <= 1e-16 * rhs) return H;
    if (fH < 0) {
      lo = H, f_lo = fH;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = H, f_hi = fH;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace remnant::rotstar
