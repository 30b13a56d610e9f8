#include "hydrostatic_balance.hpp"

#include <algorithm>
#include <cmath>

#include "TOV/tov_solver.hpp"

namespace remnant::seed {

namespace {
// Central differences of sampled functions with a known parity about r = 0 (f(-r) = parity f(r)).
std::vector<double> derivative(const std::vector<double>& f, double dr, double parity) {
  const std::size_t n = f.size();
  std::vector<double> d(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double left = k == 0 ? parity * f[1] : f[k - 1];
    d[k] = (f[k + 1] - left) / (2.0 * dr);
  }
  d[n - 1] = (f[n - 1] - f[n - 2]) / dr;
  return d;
}
}  // namespace

HydrostaticBalance::HydrostaticBalance(const tov::TovStar& star, const PoloidalLaw& law, double dr)
    : star_(star), law_(law), dr_(dr) {
  // r_cut: p_TOV(r_cut) = p_cut (p decreases outwards).
  double lo = 0.0, hi = star.isotropic_radius();
  if (!(star.at(0.0).press > law.p_cut)) hi = 0.0;
  for (int it = 0; it < 200 && hi - lo > 1e-14 * (1.0 + hi); ++it) {
    const double mid = 0.5 * (lo + hi);
    (star.at(mid).press > law.p_cut ? lo : hi) = mid;
  }
  r_cut_ = hi;
  const std::size_t n = static_cast<std::size_t>(std::ceil(r_cut_ / dr_)) + 4;
  std::vector<double> qn(n), u(n), alpha(n), psi(n), ln_alpha(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double r = static_cast<double>(k) * dr_;
    const tov::TovPoint pt = star.at(r);
    const double q = std::max(pt.press - law.p_cut, 0.0);
    qn[k] = q > 0.0 ? std::pow(q, law.n_s) : 0.0;
    u[k] = r * r * qn[k];
    alpha[k] = pt.alpha, psi[k] = pt.psi, ln_alpha[k] = std::log(pt.alpha);
  }
  // V = alpha (r^2 q^n)' / psi^2 (odd in r), G = 2 alpha q^n / psi^2 - V'.
  const std::vector<double> du = derivative(u, dr_, 1.0);
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = alpha[k] * du[k] / (psi[k] * psi[k]);
  const std::vector<double> dv = derivative(v, dr_, -1.0);
  // J^phi = A_b G / (alpha psi^6 r^2): G ~ r^2 at the centre, so the quotient is taken from
  // r = r_min on, where the differences' O(dr^2) error is small against G, and continued inwards as
  // the even function a + b r^2 through r_min and 2 r_min.
  const std::size_t k_min = std::min<std::size_t>(20, n / 4 > 1 ? n / 4 : 1);
  j_phi_.assign(n, 0.0);
  for (std::size_t k = k_min; k < n; ++k) {
    const double r = static_cast<double>(k) * dr_, psi2 = psi[k] * psi[k];
    const double G = 2.0 * alpha[k] * qn[k] / psi2 - dv[k];
    j_phi_[k] = qn[k] > 0.0 ? law.A_b * G / (alpha[k] * psi2 * psi2 * psi2 * r * r) : 0.0;
  }
  const double r1 = static_cast<double>(k_min) * dr_, r2 = 2.0 * r1;
  const double j1 = j_phi_[k_min], j2 = j_phi_[std::min(2 * k_min, n - 1)];
  const double b = (j2 - j1) / (r2 * r2 - r1 * r1), a = j1 - b * r1 * r1;
  for (std::size_t k = 0; k < k_min; ++k) {
    const double r = static_cast<double>(k) * dr_;
    j_phi_[k] = a + b * r * r;
  }
  // (dJ/dr) / (d ln alpha / dr): both odd, their quotient even and finite at the centre.
  const std::vector<double> dj = derivative(j_phi_, dr_, 1.0), dla = derivative(ln_alpha, dr_, 1.0);
  ratio_.assign(n, 0.0);
  for (std::size_t k = k_min; k < n; ++k) ratio_[k] = qn[k] > 0.0 ? dj[k] / dla[k] : 0.0;
  for (std::size_t k = 0; k < k_min; ++k) ratio_[k] = ratio_[k_min];
}

double HydrostaticBalance::sample(const std::vector<double>& f, double r) const {
  const double x = r / dr_;
  const auto k = static_cast<std::size_t>(std::floor(x));
  if (k + 1 >= f.size()) return 0.0;
  const double t = x - static_cast<double>(k);
  return (1.0 - t) * f[k] + t * f[k + 1];
}

double HydrostaticBalance::a_phi(double r, double varpi) const {
  if (!(r < r_cut_)) return 0.0;
  return law_.a_phi(varpi, star_.at(r).press);
}

double HydrostaticBalance::delta_press(double r, double varpi) const { return sample(j_phi_, r) * a_phi(r, varpi); }

double HydrostaticBalance::delta_enthalpy_density(double r, double varpi) const {
  return -a_phi(r, varpi) * sample(ratio_, r);
}

}  // namespace remnant::seed

#include "remnant/cell_geometry.hpp"

namespace remnant::seed {

BalanceChange apply_balance(const Block& b, const HydrostaticBalance& balance, Field rho, Field eps, Field press,
                            double gamma) {
  BalanceChange change;
  const CoordinateSystem c = b.coordinates;
  for_interior(b, [&](int i, int j, int k) {
    const Point3 x = cell_point(b, i, j, k);
    double r = 0.0, varpi = 0.0;
    switch (c) {
      case CoordinateSystem::cartesian: r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), varpi = std::hypot(x[0], x[1]); break;
      case CoordinateSystem::cylindrical: r = std::hypot(x[0], x[1]), varpi = std::abs(x[0]); break;
      case CoordinateSystem::spherical: r = std::abs(x[0]), varpi = std::abs(x[0] * std::sin(x[1])); break;
    }
    if (!(r < balance.field_radius())) return;
    const double dp = balance.delta_press(r, varpi), dw = balance.delta_enthalpy_density(r, varpi);
    const double p = press(i, j, k), e = rho(i, j, k) * (1.0 + eps(i, j, k));
    const double p_new = p + dp, e_new = e + dw - dp;
    const double rho_new = e_new - p_new / (gamma - 1.0);
    change.max_dp_over_p = std::max(change.max_dp_over_p, std::abs(dp) / p);
    change.max_drho_over_rho = std::max(change.max_drho_over_rho, std::abs(rho_new / rho(i, j, k) - 1.0));
    press(i, j, k) = p_new;
    rho(i, j, k) = rho_new;
    eps(i, j, k) = p_new / ((gamma - 1.0) * rho_new);
  });
  return change;
}

}  // namespace remnant::seed
