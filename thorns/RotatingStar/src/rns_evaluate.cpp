// RotatingStarModel::metric and ::at: the multipoles summed at any point (cubic Lagrange
// interpolation in r inside r_max, the exact r^-(l+1) fall-off outside), the matter from the
// Bernoulli integral at that point, so that the surface is as sharp as the output grid allows.
#include <algorithm>
#include <array>
#include <cmath>

#include "RotatingStar/rns_solver.hpp"

namespace remnant::rotstar {
namespace {

// Cubic Lagrange weights (value and r-derivative) of the nodes i0..i0+3 around r.
struct Stencil {
  int i0;
  std::array<double, 4> w, dw;
};

Stencil stencil(const std::vector<double>& nodes, double r, int n_uniform, double dr) {
  const int last = int(nodes.size()) - 1;
  int i = r <= n_uniform * dr ? int(r / dr) : int(std::upper_bound(nodes.begin(), nodes.end(), r) - nodes.begin()) - 1;
  Stencil s;
  s.i0 = std::clamp(i - 1, 0, last - 3);
  for (int a = 0; a < 4; ++a) {
    double w = 1, dw = 0;
    const double xa = nodes[s.i0 + a];
    for (int b = 0; b < 4; ++b) {
      if (b == a) continue;
      const double xb = nodes[s.i0 + b], den = xa - xb, t = (r - xb) / den;
      dw = dw * t + w / den;  // product rule, with the old w
      w *= t;
    }
    s.w[a] = w;
    s.dw[a] = dw;
  }
  return s;
}

}  // namespace

RotatingStarModel::Metric RotatingStarModel::metric(double r, double theta) const {
  const double mu = std::cos(theta), s = std::sin(theta);
  std::vector<double> P, dP, d2P;
  legendre(p_.lmax, mu, P, dP, d2P);
  Metric m{1, 1, 0, 0, 0, 0, 0, 0, 0, 0};
  double a_r = 0, a_t = 0;  // (x_r - x/r) / sin, (x_theta - x cot) / sin^2 with x = r sin X^phi
  const int N = N_;
  const double R = r_max();
  auto c_of = [&](int l, int i) { return i > 0 ? b_l_[l][i] / r_[i] : (l == 1 ? db_l_[l][0] : 0.0); };
  auto dc_of = [&](int l, int i) { return i > 0 ? (db_l_[l][i] - c_of(l, i)) / r_[i] : 0.0; };
  if (r <= R) {
    const Stencil st = stencil(r_, r, p_.nr, dr_);
    for (int l = 0; l <= p_.lmax; ++l) {
      double u1 = 0, du1 = 0, u2 = 0, du2 = 0, x = 0, dx = 0;
      for (int a = 0; a < 4; ++a) {
        const int i = st.i0 + a;
        if (l % 2 == 1) x += st.w[a] * x_l_[l][i], dx += st.w[a] * dx_l_[l][i];
        if (l % 2 == 0) {
          u1 += st.w[a] * psi_l_[l][i];
          du1 += st.w[a] * dpsi_l_[l][i];
          u2 += st.w[a] * apsi_l_[l][i];
          du2 += st.w[a] * dapsi_l_[l][i];
        } else {
          u1 += st.w[a] * c_of(l, i);
          du1 += st.w[a] * dc_of(l, i);
        }
      }
      if (l % 2 == 0) {
        m.psi += u1 * P[l], m.dpsi_r += du1 * P[l], m.dpsi_t -= s * u1 * dP[l];
        m.apsi += u2 * P[l], m.dapsi_r += du2 * P[l], m.dapsi_t -= s * u2 * dP[l];
      } else {
        m.bphi += u1 * dP[l], m.dbphi_r += du1 * dP[l], m.dbphi_t -= s * u1 * d2P[l];
        if (r > 0) a_r += (dx - x / r) * dP[l], a_t += x * d2P[l];
      }
    }
    if (r > 0) m.aa = 2 * (s * s * a_r * a_r + s * s * s * s * a_t * a_t / (r * r));
    return m;
  }
  for (int l = 0; l <= p_.lmax; ++l) {
    const double f = std::pow(R / r, l + 1);
    if (l % 2 == 0) {
      const double u1 = psi_l_[l][N] * f, u2 = apsi_l_[l][N] * f;
      m.psi += u1 * P[l], m.dpsi_r -= (l + 1) * u1 / r * P[l], m.dpsi_t -= s * u1 * dP[l];
      m.apsi += u2 * P[l], m.dapsi_r -= (l + 1) * u2 / r * P[l], m.dapsi_t -= s * u2 * dP[l];
    } else {
      const double c = b_l_[l][N] * f / r;  // b_l ~ r^-(l+1), c = b / r
      m.bphi += c * dP[l], m.dbphi_r -= (l + 2) * c / r * dP[l], m.dbphi_t -= s * c * d2P[l];
      const double x = x_l_[l][N] * f;
      a_r += (-(l + 1) * x / r - x / r) * dP[l], a_t += x * d2P[l];
    }
  }
  m.aa = 2 * (s * s * a_r * a_r + s * s * s * s * a_t * a_t / (r * r));
  return m;
}

RnsPoint RotatingStarModel::at(double r, double theta) const {
  r = std::abs(r);
  const Metric m = metric(r, theta);
  RnsPoint out;
  out.psi = m.psi;
  out.alpha = m.apsi / m.psi;
  out.beta_phi = m.bphi;
  const double mu = std::abs(std::cos(theta)), s = std::abs(std::sin(theta));
  const double x = mu * (surface_.size() - 1);
  const std::size_t k = std::min<std::size_t>(std::size_t(x), surface_.size() - 2);
  const double r_surface = surface_[k] + (x - k) * (surface_[k + 1] - surface_[k]);
  out.ye = slice_.at(0).ye;
  if (r > r_surface) return out;
  const double varpi = m.psi * m.psi * r * s;
  const auto lr = local_rotation(p_.law, omega_, A2_, varpi, out.alpha, m.bphi);
  if (!lr) return out;
  const double rhs = C_ - std::log(out.alpha) + lr->bernoulli;
  if (!(rhs > 0)) return out;
  const double H = log_enthalpy_with_field(slice_, field_, rhs, out.alpha * out.alpha * varpi * varpi);
  const tov::ColdState st = slice_.at(H);
  if (field_.active()) {
    const double rho_h = st.rho * (1 + st.eps) + st.press;
    out.B = field_.magnitude(out.alpha, varpi, rho_h);
    out.B_phi = field_.phi_component(out.alpha, m.psi, r * s, rho_h);
  }
  out.rho = st.rho, out.eps = st.eps, out.press = st.press, out.ye = st.ye;
  out.W = lr->W;
  out.vel_phi = (lr->omega + m.bphi) / out.alpha;
  out.inside = true;
  return out;
}

}  // namespace remnant::rotstar
