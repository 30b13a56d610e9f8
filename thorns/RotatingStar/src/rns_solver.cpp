// The self-consistent-field iteration of RotatingStarModel (see rns_solver.hpp): metric on the
// grid from the multipoles -> matter from the Bernoulli integral (and Omega from the axis ratio)
// -> X, psi, alpha psi, beta^phi from the new matter, until psi and alpha psi stop changing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include "RotatingStar/rns_solver.hpp"
#include "TOV/tov_solver.hpp"

namespace remnant::rotstar {
namespace {

constexpr double kPi = std::numbers::pi;

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

void check_parameters(const RnsParameters& p) {
  if (!(p.rho_central > 0)) throw RnsError(fmt("rho_central = %g must be positive", p.rho_central));
  if (!(p.omega >= 0)) throw RnsError(fmt("Omega = %g must be >= 0 (prograde rotation about +z)", p.omega));
  if (!(p.axis_ratio >= 0 && p.axis_ratio <= 1)) throw RnsError(fmt("axis ratio r_p/r_e = %g must be in (0, 1]", p.axis_ratio));
  if (p.law == RotationLaw::j_constant && !(p.A2 > 0)) throw RnsError(fmt("A^2 = %g must be positive", p.A2));
  if (p.nr < 20 || p.n_theta < 2 || p.lmax < 0 || p.lmax >= 2 * p.n_theta || !(p.r_out_factor > 1.05))
    throw RnsError("resolution: need nr >= 20, n_theta >= 2, 0 <= lmax < 2 n_theta, r_out_factor > 1.05");
}

}  // namespace

RotatingStarModel::RotatingStarModel(const tov::ColdSlice& slice, const RnsParameters& p)
    : slice_(slice), p_(p), leg_(std::max(p.n_theta, 1), std::max(p.lmax, 0)) {
  check_parameters(p_);
  Hc_ = slice.log_enthalpy(p_.rho_central);
  const double rho_back = Hc_ > 0 ? slice.at(Hc_).rho : 0;
  // 1e-3: a tabulated slice interpolates H(rho) and rho(H) separately; a clamped density is far off.
  if (!(Hc_ > 0) || std::abs(rho_back / p_.rho_central - 1) > 1e-3)
    throw RnsError(fmt("central density %g is outside the EOS slice (it gives %g)", p_.rho_central, rho_back));
  nmu_ = p_.n_theta;
  // The static star of the same central density: the radial scale and the first guess.
  const tov::TovStar tov(slice, p_.rho_central, 2000);
  dr_ = p_.r_out_factor * tov.isotropic_radius() / p_.nr;
  for (int i = 0; i <= p_.nr; ++i) r_.push_back(i * dr_);
  for (double h = 1.05 * dr_; r_.back() < p_.r_max_factor * r_out(); h *= 1.05) r_.push_back(r_.back() + h);
  N_ = int(r_.size()) - 1;
  r_e_ = r_p_ = tov.isotropic_radius();
  const int n = N_ + 1, L = p_.lmax + 1;
  for (auto* a : {&psi_l_, &dpsi_l_, &apsi_l_, &dapsi_l_, &b_l_, &db_l_, &x_l_, &dx_l_})
    a->assign(L, std::vector<double>(n, 0.0));
  for (int i = 0; i < n; ++i) {
    const tov::TovPoint t = tov.at(r_[i]);
    psi_l_[0][i] = t.psi - 1;
    apsi_l_[0][i] = t.alpha * t.psi - 1;
  }
  for (auto* f : {&psi_, &apsi_, &bphi_, &rho_, &eps_, &press_, &ye_, &W_, &v_, &omega_f_, &aa_})
    f->assign(std::size_t(n) * nmu_, 0.0);
  tov_psi_ = psi_l_[0];
  tov_apsi_ = apsi_l_[0];
  if (p_.axis_ratio == 0 && p_.omega > 0) {
    try {
      solve();
    } catch (const RnsError& direct) {
      solve_omega_by_axis_ratio(direct);  // near mass shedding the fixed-Omega iteration runs away
    }
  } else {
    solve();
  }
  compute_globals();
  const RnsGlobals& g = g_;
  for (double v : {g.M_komar, g.M_adm, g.M_rest, g.J, g.r_e, g.r_p, g.R_circ, g.omega_c, g.omega_e, g.grv2, g.grv3})
    if (!std::isfinite(v)) throw RnsError("the converged model has a non-finite global quantity: no equilibrium for these parameters");
}

void RotatingStarModel::evaluate_metric_on_grid() {
  for (int i = 0; i <= N_; ++i)
    for (int j = 0; j < nmu_; ++j) {
      double ps = 1, ap = 1, bp = 0;
      for (int l = 0; l <= p_.lmax; ++l) {
        if (l % 2 == 0) {
          ps += psi_l_[l][i] * leg_.P[l][j];
          ap += apsi_l_[l][i] * leg_.P[l][j];
        } else {
          const double c = i > 0 ? b_l_[l][i] / r_[i] : (l == 1 ? db_l_[l][0] : 0.0);
          bp += c * leg_.dP[l][j];
        }
      }
      const std::size_t k = std::size_t(i) * nmu_ + j;
      psi_[k] = ps;
      apsi_[k] = ap;
      bphi_[k] = bp;
    }
}

// Where the Bernoulli integral gives H <= 0 (or no subluminal rotation) first along the ray mu;
// -1 when the ray reaches r_out inside the star. Linear interpolation of H between grid points.
double RotatingStarModel::surface_radius(double mu, double omega, double A2) const {
  const double s = std::sqrt(std::max(0.0, 1 - mu * mu));
  double H_prev = Hc_, r_prev = 0;
  for (int i = 1; i <= p_.nr; ++i) {
    const double r = r_[i];
    const Metric m = metric(r, std::acos(mu));
    const double alpha = m.apsi / m.psi;
    const auto lr = local_rotation(p_.law, omega, A2, m.psi * m.psi * r * s, alpha, m.bphi);
    if (!lr) return r_prev;
    const double H = C_ - std::log(alpha) + lr->bernoulli;
    if (H <= 0) return r_prev + (r - r_prev) * H_prev / (H_prev - H);
    H_prev = H;
    r_prev = r;
  }
  return -1;
}

bool RotatingStarModel::matter_from_bernoulli(bool ramping) {
  const double alpha_c = apsi_[0] / psi_[0];
  C_ = Hc_ + std::log(alpha_c);
  A2_ = p_.law == RotationLaw::j_constant ? p_.A2 : 0.0;
  if (p_.axis_ratio > 0) {
    // r_p does not depend on the rotation (W = 1 on the axis); Omega puts the surface at r_p / ratio.
    r_p_ = surface_radius(1.0, 0.0, 0.0);
    if (r_p_ < 0) throw RnsError("no surface on the axis inside r_out: increase r_out_factor");
    r_e_ = r_p_ / p_.axis_ratio;
    if (r_e_ >= 0.98 * r_out())
      throw RnsError(fmt("r_e = %g reaches the grid's edge r_out = %g: the axis ratio %g is too small (increase r_out_factor, or it is beyond mass shedding)",
                         r_e_, r_out(), p_.axis_ratio));
    const Metric m = metric(r_e_, kPi / 2);
    const double alpha = m.apsi / m.psi, R = m.psi * m.psi * r_e_;
    auto H_at_re = [&](double om) {
      const auto lr = local_rotation(p_.law, om, A2_, R, alpha, m.bphi);
      return lr ? C_ - std::log(alpha) + lr->bernoulli : 1.0;
    };
    // H(r_e) rises with the rotation rate (Omega, or Omega_c of the j-constant law): bisect for
    // H(r_e) = 0. Ratio 1 is the static star (the bisection would return round-off); while the
    // metric is still too oblate for the target (H(r_e) > 0 without rotation) the star does not
    // rotate this iteration, and a model that stays so fails the final check of r_e.
    double lo = 0, hi = 4 * (alpha / R - m.bphi) + 1e-300;
    if (p_.law == RotationLaw::j_constant) hi *= 1 + std::sqrt(R * R / A2_);  // Omega_c > Omega(r_e)
    if (p_.axis_ratio < 1 && H_at_re(lo) <= 0) {
      while (H_at_re(hi) <= 0 && hi < 1e3) hi *= 2;
      for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) (H_at_re(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
      omega_ = 0.5 * (lo + hi);
    } else {
      omega_ = 0;
    }
  }
  const double ye_outside = slice_.at(0).ye;
  for (int j = 0; j < nmu_; ++j) {
    const double mu = leg_.mu[j], s = std::sqrt(1 - mu * mu);
    bool inside = true;
    for (int i = 0; i <= N_; ++i) {
      const std::size_t k = std::size_t(i) * nmu_ + j;
      if (!inside) {  // past the surface: no matter, and no root of the rotation law needed
        rho_[k] = eps_[k] = press_[k] = v_[k] = omega_f_[k] = 0;
        ye_[k] = ye_outside;
        W_[k] = 1;
        continue;
      }
      const double r = r_[i], alpha = apsi_[k] / psi_[k];
      const auto lr = local_rotation(p_.law, omega_, A2_, psi_[k] * psi_[k] * r * s, alpha, bphi_[k]);
      const double H = lr ? C_ - std::log(alpha) + lr->bernoulli : -1.0;
      inside = lr && H > 0 && i <= p_.nr;
      if (inside) {
        const tov::ColdState st = slice_.at(H);
        rho_[k] = st.rho, eps_[k] = st.eps, press_[k] = st.press, ye_[k] = st.ye;
        W_[k] = lr->W, v_[k] = lr->v, omega_f_[k] = lr->omega;
      } else {
        rho_[k] = eps_[k] = press_[k] = v_[k] = 0;
        ye_[k] = ye_outside;
        W_[k] = 1;
        omega_f_[k] = 0;
      }
      if (i == p_.nr && inside && !ramping)
        throw RnsError(fmt("no stellar surface inside r_out = %g along theta = %g: the rotation is beyond mass shedding or the star does not fit the grid (r_out_factor)",
                           r_out(), std::acos(mu)));
    }
  }
  if (p_.axis_ratio == 0) {
    const double re = surface_radius(0.0, omega_, A2_);
    if (re < 0) {
      if (ramping) return false;
      throw RnsError(fmt("no equatorial surface inside r_out = %g: Omega = %g is beyond mass shedding", r_out(), omega_));
    }
    r_e_ = re;
    r_p_ = surface_radius(1.0, omega_, A2_);
  }
  return true;
}

void RotatingStarModel::solve() {
  const bool rotating = p_.omega > 0 || (p_.axis_ratio > 0 && p_.axis_ratio < 1);
  const int ramp = rotating ? 20 : 0;
  const double target_ratio = p_.axis_ratio, target_omega = p_.omega;
  double change = 0;
  int it = 0;
  for (; it < p_.max_iterations; ++it) {
    const bool ramping = it < ramp;
    const double f = ramping ? double(it + 1) / ramp : 1.0;
    if (target_ratio > 0) p_.axis_ratio = 1 - f * (1 - target_ratio);
    else omega_ = std::sqrt(f) * target_omega;
    evaluate_metric_on_grid();
    matter_from_bernoulli(ramping);
    std::vector<std::vector<std::vector<double>>> old;
    const std::vector<std::vector<std::vector<double>>*> all{&psi_l_, &dpsi_l_, &apsi_l_, &dapsi_l_, &b_l_, &db_l_, &x_l_, &dx_l_};
    for (auto* a : all) old.push_back(*a);
    solve_potentials();
    // Under-relaxation: with the central density fixed, the plain iteration overshoots
    // (alternating, growing ~10 % per step for BU0).
    for (std::size_t q = 0; q < all.size(); ++q)
      for (int l = 0; l <= p_.lmax; ++l)
        for (int i = 0; i <= N_; ++i)
          (*all[q])[l][i] = p_.relaxation * (*all[q])[l][i] + (1 - p_.relaxation) * old[q][l][i];
    change = 0;
    for (int l = 0; l <= p_.lmax; l += 2)
      for (int i = 0; i <= N_; ++i)
        change = std::max({change, std::abs(psi_l_[l][i] - old[0][l][i]), std::abs(apsi_l_[l][i] - old[2][l][i])});
    if (!std::isfinite(change)) throw RnsError("the iteration produced NaN: no equilibrium for these parameters");
    if (!ramping && change < p_.tolerance) break;
  }
  p_.axis_ratio = target_ratio;
  if (it == p_.max_iterations)
    throw RnsError(fmt("no convergence in %g iterations (last change %g): no equilibrium for these parameters (beyond mass shedding or unstable)",
                       p_.max_iterations, change));
  g_.iterations = it + 1;
  evaluate_metric_on_grid();
  matter_from_bernoulli(false);
  if (p_.axis_ratio > 0) {
    // Beyond mass shedding H dips below zero before r_e on the equator.
    const double re = surface_radius(0.0, omega_, A2_);
    if (std::abs(re - r_e_) > 1e-3 * r_e_)
      throw RnsError(fmt("axis ratio %g is beyond the mass-shedding limit (the equatorial surface sits at %g, not at r_e = %g)",
                         p_.axis_ratio, re, r_e_));
  }
}

void RotatingStarModel::restart_from_tov() {
  for (auto* a : {&psi_l_, &dpsi_l_, &apsi_l_, &dapsi_l_, &b_l_, &db_l_, &x_l_, &dx_l_})
    for (auto& f : *a) std::fill(f.begin(), f.end(), 0.0);
  psi_l_[0] = tov_psi_;
  apsi_l_[0] = tov_apsi_;
  omega_ = 0;
}

// Omega(r_p/r_e) rises monotonically from 0 at ratio 1 to the Kepler rate at mass shedding, and the
// axis-ratio iteration stays stable there: find the ratio whose Omega is the target, by regula falsi
// (Illinois) between a slower model and a faster one or a failed (beyond-shedding) ratio, which is
// then bisected. A target above every model's Omega is beyond shedding: the direct error stands.
void RotatingStarModel::solve_omega_by_axis_ratio(const RnsError& direct) {
  const double target = p_.omega;
  auto omega_at = [&](double q) -> std::optional<double> {
    restart_from_tov();
    p_.axis_ratio = q;
    p_.omega = 0;
    try {
      solve();
    } catch (const RnsError&) {
      return std::nullopt;
    }
    return omega_;
  };
  // Bracket: q_slow has Omega < target (ratio 1: Omega = 0); q_fast has Omega > target or failed.
  double q_slow = 1, f_slow = -target, q_fast = 0, f_fast = 0;
  bool fast_valid = false;
  for (double q = 0.9; q > 0.3; q -= 0.1) {
    const auto om = omega_at(q);
    if (om && *om < target) { q_slow = q, f_slow = *om - target; continue; }
    q_fast = q, fast_valid = bool(om), f_fast = om ? *om - target : 0;
    break;
  }
  if (q_fast == 0) throw direct;
  int side = 0;
  for (int it = 0; it < 60; ++it) {
    double q = 0.5 * (q_slow + q_fast);
    if (fast_valid) q = (q_slow * f_fast - q_fast * f_slow) / (f_fast - f_slow);
    const auto om = omega_at(q);
    if (om && std::abs(*om / target - 1) < 1e-9) {
      p_.axis_ratio = 0;
      p_.omega = target;
      return;
    }
    if (om && *om < target) {
      q_slow = q, f_slow = *om - target;
      if (side == -1 && fast_valid) f_fast *= 0.5;  // Illinois: the stale end's weight halves
      side = -1;
    } else {
      q_fast = q, fast_valid = bool(om), f_fast = om ? *om - target : 0;
      if (side == 1) f_slow *= 0.5;
      side = 1;
    }
    if (q_slow - q_fast < 1e-7) break;  // Omega(q) is flat at shedding: 1e-7 in q is < 1e-7 in Omega
    // Within 1e-3 of the shedding ratio Omega changes by ~1e-4 (BU sequence): 1e-3 short is out of reach.
    if (!fast_valid && q_slow - q_fast < 1e-3 && f_slow < -1e-3 * target) break;
  }
  p_.axis_ratio = 0;
  p_.omega = target;
  if (fast_valid) throw direct;
  throw RnsError(fmt("Omega = %.7g is beyond mass shedding: the fastest equilibrium of this central density rotates at Omega = %.7g (r_p/r_e = %.5f)",
                     target, f_slow + target, q_slow));
}

void RotatingStarModel::solve_potentials() {
  const int n = N_ + 1;
  const std::size_t N = std::size_t(n) * nmu_;
  std::vector<double> E(N), S(N), Sphi(N), src(N);  // Sphi = S_phi / (r sin theta)
  for (std::size_t k = 0; k < N; ++k) {
    const double h = 1 + eps_[k] + (rho_[k] > 0 ? press_[k] / rho_[k] : 0), w = rho_[k] * h * W_[k] * W_[k];
    E[k] = w - press_[k];
    S[k] = w * v_[k] * v_[k] + 3 * press_[k];
    Sphi[k] = w * psi_[k] * psi_[k] * v_[k];
  }
  auto solve_m1 = [&](std::vector<std::vector<double>>& u, std::vector<std::vector<double>>& du) {
    for (int l = 1; l <= p_.lmax; l += 2) {
      RadialSolution r = solve_radial(l, r_, project_m1(leg_, l, src, n));
      u[l] = std::move(r.u);
      du[l] = std::move(r.du);
    }
  };
  auto solve_scalar = [&](std::vector<std::vector<double>>& u, std::vector<std::vector<double>>& du) {
    for (int l = 0; l <= p_.lmax; l += 2) {
      RadialSolution r = solve_radial(l, r_, project_scalar(leg_, l, src, n));
      u[l] = std::move(r.u);
      du[l] = std::move(r.du);
    }
  };
  // X, then A_ij A^ij = 2 [(x_r - x/r)^2 + (x_theta - x cot(theta))^2 / r^2] with x = r sin(theta) X^phi.
  for (std::size_t k = 0; k < N; ++k) src[k] = 8 * kPi * std::pow(psi_[k], 6) * Sphi[k];
  solve_m1(x_l_, dx_l_);
  std::vector<double> ar(N, 0.0), at(N, 0.0);
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < nmu_; ++j) {
      const double r = r_[i], s2 = 1 - leg_.mu[j] * leg_.mu[j], s = std::sqrt(s2);
      double a = 0, b = 0;
      for (int l = 1; l <= p_.lmax; l += 2) {
        a += (dx_l_[l][i] - x_l_[l][i] / r) * leg_.dP[l][j];
        b += x_l_[l][i] * leg_.d2P[l][j];
      }
      const std::size_t k = std::size_t(i) * nmu_ + j;
      ar[k] = s * a;
      at[k] = -s2 * b;
      aa_[k] = 2 * (ar[k] * ar[k] + at[k] * at[k] / (r * r));
    }
  for (std::size_t k = 0; k < N; ++k) src[k] = -2 * kPi * std::pow(psi_[k], 5) * E[k] - aa_[k] / (8 * std::pow(psi_[k], 7));
  solve_scalar(psi_l_, dpsi_l_);
  evaluate_metric_on_grid();  // the new psi
  for (std::size_t k = 0; k < N; ++k)
    src[k] = apsi_[k] * (2 * kPi * std::pow(psi_[k], 4) * (E[k] + 2 * S[k]) + 7.0 / 8 * aa_[k] / std::pow(psi_[k], 8));
  solve_scalar(apsi_l_, dapsi_l_);
  evaluate_metric_on_grid();  // the new alpha psi
  // beta: 16 pi alpha S_phi / (r sin) + 2 [(x_r - x/r) d_r q + (x_th - x cot) d_th q / r^2], q = alpha psi^-6.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < nmu_; ++j) {
      const std::size_t k = std::size_t(i) * nmu_ + j;
      const double r = r_[i], s = std::sqrt(1 - leg_.mu[j] * leg_.mu[j]);
      double dps_r = 0, dps_t = 0, dap_r = 0, dap_t = 0;
      for (int l = 0; l <= p_.lmax; l += 2) {
        dps_r += dpsi_l_[l][i] * leg_.P[l][j];
        dps_t -= s * psi_l_[l][i] * leg_.dP[l][j];
        dap_r += dapsi_l_[l][i] * leg_.P[l][j];
        dap_t -= s * apsi_l_[l][i] * leg_.dP[l][j];
      }
      const double ps = psi_[k], ap = apsi_[k], p7 = std::pow(ps, -7);
      const double dq_r = p7 * dap_r - 7 * ap * p7 / ps * dps_r, dq_t = p7 * dap_t - 7 * ap * p7 / ps * dps_t;
      src[k] = 16 * kPi * (ap / ps) * Sphi[k] + (i > 0 ? 2 * (ar[k] * dq_r + at[k] * dq_t / (r * r)) : 0.0);
    }
  solve_m1(b_l_, db_l_);
}

}  // namespace remnant::rotstar
