#pragma once
// The TOV equations in isotropic coordinates: integrated in the log-enthalpy from the centre to the
// surface (Lindblom 1992, ApJ 398, 569), r(H), m(H), the isotropic radius and the rest mass, with a
// GSL Runge-Kutta-Fehlberg integrator; matched to exterior Schwarzschild in isotropic coordinates:
//   psi = 1 + M / (2 rbar), alpha = (1 - M / (2 rbar)) / (1 + M / (2 rbar)),
// and inside alpha = sqrt(1 - 2M/R) e^{-H} (alpha h is constant in a static star), psi^2 = r / rbar.
#include <memory>
#include <vector>

#include "TOV/cold_slice.hpp"

namespace remnant::tov {

struct TovPoint {
  double rho = 0, eps = 0, press = 0, ye = 0, psi = 1, alpha = 1;
  bool inside = false;
};

class TovStar {
 public:
  TovStar(const ColdSlice& slice, double rho_central, int samples = 4000);
  TovPoint at(double rbar) const;  // isotropic radius
  double gravitational_mass() const { return M_; }
  double rest_mass() const { return M0_; }
  double areal_radius() const { return R_; }
  double isotropic_radius() const { return Rbar_; }
  double central_log_enthalpy() const { return Hc_; }

 private:
  const ColdSlice& slice_;
  double M_ = 0, M0_ = 0, R_ = 0, Rbar_ = 0, Hc_ = 0;
  std::vector<double> rbar_, H_, lnpsi_;  // profile, rbar increasing from 0 to Rbar
  struct Interp;
  std::shared_ptr<Interp> interp_;
};

}  // namespace remnant::tov
