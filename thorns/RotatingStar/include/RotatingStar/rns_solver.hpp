#pragma once
// Stationary axisymmetric rotating stars in the xCFC approximation (the formalism of XNS:
// Bucciantini & Del Zanna 2011, A&A 528, A101), solved by a self-consistent-field iteration on a
// spherical (r, theta) grid with equatorial symmetry:
//   X^phi:    Delta_vec X = 8 pi f^ij S*_j                          (m = 1 multipoles)
//   psi:      Delta psi = -2 pi psi^5 E - psi^-7 A_ij A^ij / 8       (A^ij = (LX)^ij)
//   alpha psi: Delta(alpha psi) = alpha psi [2 pi psi^4 (E + 2S) + 7/8 psi^-8 A_ij A^ij]
//   beta^phi: Delta_vec beta = 16 pi alpha f^ij S_j + 2 A^ij d_j(alpha psi^-6)
// each as a sum over Legendre multipoles solved exactly in r by Green's functions (multipoles.hpp)
// on radial nodes uniform to r_out and stretched far beyond (the A_ij A^ij sources outside the star
// fall off only as r^-6 and carry ~1e-3 of the mass within 2 stellar radii),
// and the matter from the Bernoulli integral of the rotation law (rotation_law.hpp) with the
// central density held fixed. The target is either Omega (Omega_c) or the axis ratio r_p / r_e,
// in which case Omega follows each iteration from H = 0 at r_e on the equator.
// Bad parameters (no surface before the grid's edge, v >= 1, no convergence) throw RnsError.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "RotatingStar/multipoles.hpp"
#include "RotatingStar/rotation_law.hpp"
#include "TOV/cold_slice.hpp"

namespace remnant::rotstar {

struct RnsError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RnsParameters {
  double rho_central = 1.28e-3;
  RotationLaw law = RotationLaw::uniform;
  double omega = 0;       // uniform Omega, or Omega_c of the j-constant law (used when axis_ratio == 0)
  double axis_ratio = 0;  // (0:1]: target r_p / r_e, the rotation rate is found
  double A2 = 70;         // j-constant law: A^2 in code units (M_sun^2); the paper's magnetized-DRNS: 70
  int nr = 800;           // uniform radial intervals to r_out (the star lies inside)
  double r_out_factor = 2.0;  // r_out = r_out_factor * (isotropic radius of the static star)
  double r_max_factor = 200;  // beyond r_out the grid stretches by 5 % per interval to r_max = this * r_out
  int n_theta = 24;       // Gauss nodes in 0 < theta < pi/2
  int lmax = 20;          // highest multipole
  int max_iterations = 1000;
  double relaxation = 0.5;  // new = relaxation * solved + (1 - relaxation) * old
  double tolerance = 1e-11;  // max change of psi and alpha psi between iterations
};

struct RnsGlobals {
  double M_komar = 0, M_adm = 0, M_rest = 0, M_proper = 0, J = 0, T_kin = 0, W_bind = 0, T_over_W = 0;
  double r_e = 0, r_p = 0, R_circ = 0, axis_ratio = 0, omega_c = 0, omega_e = 0;
  double rho_c = 0, rho_max = 0, alpha_c = 0, psi_c = 0;
  double grv2 = 0, grv3 = 0;        // virial identities of the xCFC system (accuracy)
  double grv2_gr = 0, grv3_gr = 0;  // GR's identities (conformal-flatness error + accuracy)
  int iterations = 0;
};

struct RnsPoint {
  double rho = 0, eps = 0, press = 0, ye = 0;
  double psi = 1, alpha = 1, beta_phi = 0;  // coordinate component beta^phi
  double vel_phi = 0, W = 1;                // coordinate component v^phi of the Eulerian velocity
  bool inside = false;
};

class RotatingStarModel {
 public:
  RotatingStarModel(const tov::ColdSlice& slice, const RnsParameters& p);
  // The model at the point (r, theta) of flat spherical coordinates (any r >= 0, theta in [0, pi]).
  RnsPoint at(double r, double theta) const;
  const RnsGlobals& globals() const { return g_; }
  const RnsParameters& parameters() const { return p_; }
  double r_out() const { return dr_ * p_.nr; }
  double r_max() const { return r_.back(); }
  // The metric potentials and their r and theta derivatives at a point (used by at() and GRV2).
  struct Metric {
    double psi, apsi, bphi, dpsi_r, dpsi_t, dapsi_r, dapsi_t, dbphi_r, dbphi_t;
    double aa;  // A_ij A^ij from X
  };
  Metric metric(double r, double theta) const;

 private:
  void solve();
  void restart_from_tov();
  void solve_omega_by_axis_ratio(const RnsError& direct);
  void evaluate_metric_on_grid();
  bool matter_from_bernoulli(bool ramping);
  void solve_potentials();
  void compute_globals();
  double surface_radius(double mu, double omega, double A2) const;

  const tov::ColdSlice& slice_;
  RnsParameters p_;
  LegendreTable leg_;
  double dr_ = 0, Hc_ = 0, C_ = 0, omega_ = 0, A2_ = 0, r_e_ = 0, r_p_ = 0;
  int nmu_ = 0, N_ = 0;        // N_: the last radial node
  std::vector<double> tov_psi_, tov_apsi_;  // the first guess's monopoles (restarts)
  std::vector<double> r_;      // radial nodes: uniform (dr_) to r_out, then stretched to r_max
  // Multipole radial functions [l][i]: psi - 1 and alpha psi - 1 (even l), b / r = sum b_l / r P_l'
  // with b = r sin(theta) beta^phi and x likewise for X (odd l); with r-derivatives.
  std::vector<std::vector<double>> psi_l_, dpsi_l_, apsi_l_, dapsi_l_, b_l_, db_l_, x_l_, dx_l_;
  // Grid fields [i * nmu + j] on the Gauss rays.
  std::vector<double> psi_, apsi_, bphi_, rho_, eps_, press_, ye_, W_, v_, omega_f_, aa_;
  std::vector<double> surface_;  // surface radius at mu = k / (size - 1), for at()
  RnsGlobals g_;
};

}  // namespace remnant::rotstar
