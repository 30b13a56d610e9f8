// Global quantities of a converged model: masses, J, T/|W|, radii, rotation rates and the virial
// identities. Volume integrals: trapezoidal rule in r, the Gauss rule in mu (both hemispheres).
//   M_rest = int rho W psi^6 dV, M_proper = int rho (1 + eps) W psi^6 dV,
//   M_Komar = int [alpha (E + S) - 2 beta^phi S_phi] psi^6 dV, J = int S_phi psi^6 dV,
//   T = int Omega S_phi psi^6 dV / 2, |W| = M_proper + T - M_Komar;
//   M_ADM from the monopole of psi (psi -> 1 + M / 2r).
// GRV2 (Bonazzola 1973; Bonazzola & Gourgoulhon 1994) with A = B = psi^2, N = alpha,
// omega = -beta^phi, nu = ln alpha, over the meridional plane (r dr dtheta, theta in [0, pi]):
//   int [8 pi psi^4 S^phi_phi + 3/4 psi^4 r^2 sin^2 (d beta^phi)^2 / alpha^2 - (d nu)^2] = 0;
// the exterior (r > r_out) from the multipoles' fall-off with r = r_out / t.
// GRV3 in the form M_Komar = M_ADM, to which it is equivalent for stationary asymptotically flat
// spacetimes (Gourgoulhon & Bonazzola 1994). In xCFC neither identity holds exactly for a rotating
// star: both measure the discretisation error plus the conformal-flatness error.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "RotatingStar/rns_solver.hpp"

namespace remnant::rotstar {

void RotatingStarModel::compute_globals() {
  constexpr double kPi = std::numbers::pi;
  const int n = p_.nr + 1;
  double M0 = 0, Mp = 0, MK = 0, J = 0, T = 0, grv2_pos = 0, grv2_neg = 0;
  for (int i = 0; i < n; ++i) {
    const double r = i * dr_, tw = (i == 0 || i == n - 1) ? 0.5 : 1.0;
    for (int j = 0; j < nmu_; ++j) {
      const std::size_t k = std::size_t(i) * nmu_ + j;
      const double mu = leg_.mu[j], s = std::sqrt(1 - mu * mu);
      const double dV = 2 * kPi * 2 * leg_.weight[j] * r * r * dr_ * tw;
      const double ps = psi_[k], p6 = std::pow(ps, 6), alpha = apsi_[k] / ps;
      const double h = 1 + eps_[k] + (rho_[k] > 0 ? press_[k] / rho_[k] : 0), w = rho_[k] * h * W_[k] * W_[k];
      const double E = w - press_[k], S = w * v_[k] * v_[k] + 3 * press_[k];
      const double Sphi = w * v_[k] * ps * ps * r * s;
      M0 += rho_[k] * W_[k] * p6 * dV;
      Mp += rho_[k] * (1 + eps_[k]) * W_[k] * p6 * dV;
      MK += (alpha * (E + S) - 2 * bphi_[k] * Sphi) * p6 * dV;
      J += Sphi * p6 * dV;
      T += 0.5 * omega_f_[k] * Sphi * p6 * dV;
      if (i > 0) {
        // GRV2 in r dr dtheta: dtheta = dmu / sin(theta), both hemispheres.
        const double dA = 2 * leg_.weight[j] / s * r * dr_ * tw;
        const Metric m = metric(r, std::acos(mu));
        const double nu_r = m.dapsi_r / m.apsi - m.dpsi_r / m.psi, nu_t = (m.dapsi_t / m.apsi - m.dpsi_t / m.psi) / r;
        const double db2 = m.dbphi_r * m.dbphi_r + m.dbphi_t * m.dbphi_t / (r * r);
        grv2_pos += (8 * kPi * std::pow(ps, 4) * (w * v_[k] * v_[k] + press_[k]) +
                     0.75 * std::pow(ps, 4) * r * r * s * s * db2 / (alpha * alpha)) * dA;
        grv2_neg += (nu_r * nu_r + nu_t * nu_t) * dA;
      }
    }
  }
  // Exterior of the GRV2 field terms: r = r_out / t, dr = r_out dt / t^2, Gauss rule in t.
  const LegendreTable tq(32, 0);
  for (int q = 0; q < 32; ++q)
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      const double t = 0.5 * (1 + sgn * tq.mu[q]), wt = 0.5 * tq.weight[q], r = r_out() / t;
      for (int j = 0; j < nmu_; ++j) {
        const double mu = leg_.mu[j], s = std::sqrt(1 - mu * mu);
        const Metric m = metric(r, std::acos(mu));
        const double alpha = m.apsi / m.psi;
        const double nu_r = m.dapsi_r / m.apsi - m.dpsi_r / m.psi, nu_t = (m.dapsi_t / m.apsi - m.dpsi_t / m.psi) / r;
        const double db2 = m.dbphi_r * m.dbphi_r + m.dbphi_t * m.dbphi_t / (r * r);
        const double dA = 2 * leg_.weight[j] / s * r * (r_out() * wt / (t * t));
        grv2_pos += 0.75 * std::pow(m.psi, 4) * r * r * s * s * db2 / (alpha * alpha) * dA;
        grv2_neg += (nu_r * nu_r + nu_t * nu_t) * dA;
      }
    }
  g_.M_rest = M0;
  g_.M_proper = Mp;
  g_.M_komar = MK;
  g_.M_adm = 2 * r_out() * psi_l_[0][p_.nr];
  g_.J = J;
  g_.T_kin = T;
  g_.W_bind = Mp + T - MK;
  g_.T_over_W = T / std::abs(g_.W_bind);
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
  g_.grv2 = std::abs(1 - grv2_pos / grv2_neg);
  g_.grv3 = std::abs(1 - g_.M_komar / g_.M_adm);
  // Surface radius table for at().
  surface_.resize(257);
  for (std::size_t k = 0; k < surface_.size(); ++k) {
    const double rs = surface_radius(double(k) / (surface_.size() - 1), omega_, A2_);
    surface_[k] = rs < 0 ? r_out() : rs;
  }
}

}  // namespace remnant::rotstar
