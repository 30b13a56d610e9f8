#pragma once
// SeedMagneticField::balance = hydrostatic: the poloidal field's Lorentz force balanced by the
// fluid of a static spherical (TOV) star, the field kept exactly as seeded (README.md, "Balance").
//
// Static fluid in the star's metric (alpha, psi spherical):  d_i p + w d_i ln(alpha) = f_i,
// w = e + p, f_i = (J x B)_i with alpha J = curl(alpha B). For the poloidal field of a potential
// A_phi(r, theta) (covariant phi component, B^i = eps^ijk d_j A_k) only J^phi survives and
// f_i = J^phi d_i A_phi. For A_phi = A_b varpi^2 q(r)^n_s (q = max(p_TOV - p_cut, 0), p_TOV spherical)
// J^phi = A_b G(r) / (alpha psi^6 r^2),  G = 2 alpha q^n / psi^2 - d/dr[alpha (r^2 q^n)' / psi^2],
// depends on r only, so the perturbation of the TOV star that balances f is, in closed form,
//   delta p = J^phi A_phi,          (theta equation; delta p = 0 on the axis and where A_phi = 0)
//   delta w = -A_phi (dJ^phi/dr) / (d ln alpha / dr)   (r equation).
// Outside the field's region (A_phi = 0) the star is the TOV star exactly. The metric is the TOV
// star's: the change of alpha that delta w, delta p and the field's energy make is not included.
#include <vector>

#include "field_laws.hpp"

namespace remnant::tov {
class TovStar;
}

namespace remnant::seed {

class HydrostaticBalance {
 public:
  // law: the seeded potential's A_b, p_cut, n_s; the profile is sampled every dr up to where
  // p_TOV = p_cut.
  HydrostaticBalance(const tov::TovStar& star, const PoloidalLaw& law, double dr = 0.01);
  // delta p and delta w at isotropic radius r and coordinate cylindrical radius varpi.
  double delta_press(double r, double varpi) const;
  double delta_enthalpy_density(double r, double varpi) const;
  double field_radius() const { return r_cut_; }  // A_phi = 0 outside

 private:
  double a_phi(double r, double varpi) const;
  double sample(const std::vector<double>& f, double r) const;
  const tov::TovStar& star_;
  PoloidalLaw law_;
  double dr_ = 0.01, r_cut_ = 0.0;
  std::vector<double> j_phi_, ratio_;  // J^phi(r) and (dJ^phi/dr) / (d ln alpha / dr) at r = k dr
};

}  // namespace remnant::seed

#include "remnant/grid.hpp"

namespace remnant::seed {

// Adds the balance's delta p and delta w to the interior cells of a block (cell-centre point values,
// as TOV writes them): p += delta p, e = rho (1 + eps) += delta w - delta p, then rho and eps from
// the ideal gas with adiabatic index gamma (rho eps = p / (gamma - 1)). Returns the largest
// |delta p| / p and |delta rho| / rho changed.
struct BalanceChange {
  double max_dp_over_p = 0.0, max_drho_over_rho = 0.0;
};
BalanceChange apply_balance(const Block& b, const HydrostaticBalance& balance, Field rho, Field eps, Field press,
                            double gamma);

}  // namespace remnant::seed
