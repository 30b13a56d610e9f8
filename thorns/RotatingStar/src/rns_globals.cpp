// Global quantities of a converged model: masses, J, T/|W|, radii, rotation rates and the virial
// identities. Volume integrals: trapezoidal rule in r, the Gauss rule in mu (both hemispheres).
//   M_rest = int rho W psi^6 dV, M_proper = int rho (1 + eps) W psi^6 dV,
//   M_Komar = int [alpha (E + S) - 2 beta^phi S_phi] psi^6 dV, J = int S_phi psi^6 dV,
//   T = int Omega S_phi psi^6 dV / 2, H = int B^2 / 2 psi^6 dV (toroidal field), |W| = M_proper + T + H - M_Komar;
// with a toroidal field E, S and S^phi_phi carry its energy and stresses (magnetic_law.hpp).
//   M_ADM from the monopole of psi (psi -> 1 + M / 2r).
// Virial identities. GR's (Bonazzola & Gourgoulhon 1994) do not hold in xCFC for a rotating star:
// with A = B = psi^2, N = alpha, omega = -beta^phi, nu = ln alpha, over the meridional plane
// (r dr dtheta, theta in [0, pi]),
//   GRV2_GR: int [8 pi psi^4 S^phi_phi + 3/4 psi^4 r^2 sin^2 (d beta^phi)^2 / alpha^2 - (d nu)^2] = 0,
//   GRV3_GR: M_Komar = M_ADM (equivalent to GRV3 for stationary asymptotically flat spacetimes),
// measure the conformal-flatness error (O(Omega^2)) plus the discretisation error. The identities
// of the xCFC system itself, the same construction for zeta = ln(alpha psi^2) = ln A N, whose
// Laplacian follows from the psi and alpha psi equations,
//   Delta_3 zeta = 4 pi psi^4 S + 3/4 psi^-8 A_ij A^ij - (d ln alpha psi)^2 - (d ln psi)^2,
//   GRV2: int Delta_2 zeta r dr dtheta = 0, with Delta_2 = Delta_3 - d_varpi / varpi,
//   GRV3: int Delta_3 zeta d^3x = -2 pi (M_ADM - M_alpha psi) (the 1/r fall-off of zeta),
// hold for every exact xCFC equilibrium: they measure the solver's accuracy (relative residuals).
// Outside r_out the field terms are integrated by the Gauss rule in t = r_out / r.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "RotatingStar/rns_solver.hpp"

namespace remnant::rotstar {

void RotatingStarModel::compute_globals() {
  constexpr double kPi = std::numbers::pi;
  // Surface radius table for at().
  surface_.resize(257);
  for (std::size_t k = 0; k < surface_.size(); ++k) {
    const double rs = surface_radius(double(k) / (surface_.size() - 1), omega_, A2_);
    surface_[k] = rs < 0 ? r_out() : rs;
  }
  double M0 = 0, Mp = 0, MK = 0, J = 0, T = 0, Hm = 0;
  double gr2_pos = 0, gr2_neg = 0, x2_pos = 0, x2_neg = 0, x3_pos = 0, x3_neg = 0;
  // Field terms of the identities at (r, theta) with S = S^i_i, Sphiphi = S^phi_phi there;
  // dA = r dr dtheta (meridional plane, both hemispheres), dV = r^2 dr dOmega.
  auto identities = [&](double r, double theta, double S, double Sphiphi, double dA, double dV) {
    const double mu = std::cos(theta), s = std::sin(theta);
    const Metric m = metric(r, theta);
    const double alpha = m.apsi / m.psi, p4 = std::pow(m.psi, 4);
    const double lp_r = m.dpsi_r / m.psi, lp_t = m.dpsi_t / (m.psi * r);      // d ln psi
    const double la_r = m.dapsi_r / m.apsi, la_t = m.dapsi_t / (m.apsi * r);  // d ln(alpha psi)
    const double nu2 = (la_r - lp_r) * (la_r - lp_r) + (la_t - lp_t) * (la_t - lp_t);
    const double db2 = m.dbphi_r * m.dbphi_r + m.dbphi_t * m.dbphi_t / (r * r);
    gr2_pos += (8 * kPi * p4 * Sphiphi + 0.75 * p4 * r * r * s * s * db2 / (alpha * alpha)) * dA;
    gr2_neg += nu2 * dA;
    // zeta = ln(alpha psi^2): Delta_3 zeta from the xCFC equations, Delta_2 = Delta_3 - d_varpi / varpi.
    const double src = 4 * kPi * p4 * S + 0.75 * m.aa / std::pow(m.psi, 8);
    const double grad2 = la_r * la_r + la_t * la_t + lp_r * lp_r + lp_t * lp_t;
    const double z_r = la_r + lp_r, z_t = la_t + lp_t;  // z_t = (1/r) d_theta zeta
    x2_pos += src * dA;
    x2_neg += (grad2 + z_r / r + mu * z_t / (r * s)) * dA;
    x3_pos += src * dV;
    x3_neg += grad2 * dV;
  };
  // Outside r_out (no matter): the Gauss rule in t = r_out / r, dr = r_out dt / t^2.
  const LegendreTable tq(32, 0);
  auto exterior = [&](auto&& f) {
    for (int q = 0; q < 32; ++q)
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        const double t = 0.5 * (1 + sgn * tq.mu[q]);
        f(r_out() / t, r_out() * 0.5 * tq.weight[q] / (t * t));
      }
  };
  // Volume integrals: the matter lies inside r_out, trapezoidal rule on the uniform nodes, the
  // Gauss rule in mu (the integrands are smooth in mu); the 3D identity's field terms likewise.
  for (int i = 0; i <= p_.nr; ++i) {
    const double r = r_[i], dr = (i == 0 || i == p_.nr) ? 0.5 * dr_ : dr_;
    for (int j = 0; j < nmu_; ++j) {
      const std::size_t k = std::size_t(i) * nmu_ + j;
      const double mu = leg_.mu[j], s = std::sqrt(1 - mu * mu);
      const double dV = 2 * kPi * 2 * leg_.weight[j] * r * r * dr;
      const double ps = psi_[k], p6 = std::pow(ps, 6), alpha = apsi_[k] / ps;
      const double h = 1 + eps_[k] + (rho_[k] > 0 ? press_[k] / rho_[k] : 0), w = rho_[k] * h * W_[k] * W_[k];
      const double pm = 0.5 * B_[k] * B_[k];
      const double E = w - press_[k] + pm, S = w * v_[k] * v_[k] + 3 * press_[k] + pm;
      const double Sphi = w * v_[k] * ps * ps * r * s;
      M0 += rho_[k] * W_[k] * p6 * dV;
      Mp += rho_[k] * (1 + eps_[k]) * W_[k] * p6 * dV;
      MK += (alpha * (E + S) - 2 * bphi_[k] * Sphi) * p6 * dV;
      J += Sphi * p6 * dV;
      T += 0.5 * omega_f_[k] * Sphi * p6 * dV;
      Hm += pm * p6 * dV;
      if (i > 0) identities(r, std::acos(mu), S, 0, 0, dV);
    }
  }
  exterior([&](double r, double dr) {
    for (int j = 0; j < nmu_; ++j)
      identities(r, std::acos(leg_.mu[j]), 0, 0, 0, 2 * kPi * 2 * leg_.weight[j] * r * r * dr);
  });
  // Meridional-plane integrals (GRV2): r dr dtheta has no sin(theta), so the midpoint rule in theta
  // (spectral for these even, periodic integrands) instead of the Gauss rule in mu; matter from at().
  const int nth = 64;
  const double dth = kPi / 2 / nth;
  for (int i = 1; i <= p_.nr; ++i) {
    const double r = r_[i], dr = i == p_.nr ? 0.5 * dr_ : dr_;
    for (int j = 0; j < nth; ++j) {
      const double th = (j + 0.5) * dth;
      const RnsPoint q = at(r, th);
      const double h = 1 + q.eps + (q.rho > 0 ? q.press / q.rho : 0), v = q.psi * q.psi * r * std::sin(th) * q.vel_phi;
      const double wv2 = q.rho * h * q.W * q.W * v * v, pm = 0.5 * q.B * q.B;
      // The toroidal field's stresses: S += B^2/2, S^phi_phi -= B^2/2 (tension along phi).
      identities(r, th, wv2 + 3 * q.press + pm, wv2 + q.press - pm, 2 * r * dr * dth, 0);
    }
  }
  exterior([&](double r, double dr) {
    for (int j = 0; j < nth; ++j) identities(r, (j + 0.5) * dth, 0, 0, 2 * r * dr * dth, 0);
  });
  g_.M_rest = M0;
  g_.M_proper = Mp;
  g_.M_komar = MK;
  g_.M_adm = 2 * r_max() * psi_l_[0][N_];
  g_.J = J;
  g_.T_kin = T;
  g_.H_mag = Hm;
  g_.W_bind = Mp + T + Hm - MK;  // M_komar = M_proper + T + H - |W|
  g_.T_over_W = T / std::abs(g_.W_bind);
  g_.H_over_W = Hm / std::abs(g_.W_bind);
  g_.B_max = *std::max_element(B_.begin(), B_.end());
  g_.r_e = r_e_;
  g_.r_p = r_p_;
  g_.axis_ratio = r_p_ / r_e_;
  g_.R_circ = std::pow(metric(r_e_, kPi / 2).psi, 2) * r_e_;
  g_.omega_c = omega_;
  const Metric me = metric(r_e_, kPi / 2);
  const auto lr = local_rotation(p_.law, omega_, A2_, me.psi * me.psi * r_e_, me.apsi / me.psi, me.bphi);
  g_.omega_e = lr ? lr->omega : omega_;
  g_.rho_c = rho_[0];
  g_.rho_max = *std::max_element(rho_.begin(), rho_.end());
  g_.psi_c = psi_[0];
  g_.alpha_c = apsi_[0] / psi_[0];
  const double M_apsi = -2 * r_max() * apsi_l_[0][N_];  // alpha psi -> 1 - M_apsi / 2r
  g_.grv2 = std::abs(1 - x2_pos / x2_neg);
  g_.grv3 = std::abs(1 - x3_pos / (x3_neg - 2 * kPi * (g_.M_adm - M_apsi)));
  g_.grv2_gr = std::abs(1 - gr2_pos / gr2_neg);
  g_.grv3_gr = std::abs(1 - g_.M_komar / g_.M_adm);
}

}  // namespace remnant::rotstar
