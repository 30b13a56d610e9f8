#include "RotatingStar/multipoles.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace remnant::rotstar {

void legendre(int lmax, double mu, std::vector<double>& P, std::vector<double>& dP, std::vector<double>& d2P) {
  P.assign(lmax + 1, 0.0);
  dP.assign(lmax + 1, 0.0);
  d2P.assign(lmax + 1, 0.0);
  P[0] = 1;
  if (lmax >= 1) P[1] = mu, dP[1] = 1;
  for (int l = 1; l < lmax; ++l) {
    P[l + 1] = ((2 * l + 1) * mu * P[l] - l * P[l - 1]) / (l + 1);
    // P_{l+1}' = P_{l-1}' + (2l+1) P_l, and its derivative: no division by 1 - mu^2 at the poles.
    dP[l + 1] = dP[l - 1] + (2 * l + 1) * P[l];
    d2P[l + 1] = d2P[l - 1] + (2 * l + 1) * dP[l];
  }
}

LegendreTable::LegendreTable(int n_half, int lmax_) : lmax(lmax_) {
  // Gauss-Legendre nodes of the 2 n_half rule by Newton's iteration; keep mu > 0.
  const int n = 2 * n_half;
  for (int k = 0; k < n_half; ++k) {
    double x = std::cos(std::numbers::pi * (k + 0.75) / (n + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int l = 1; l < n; ++l) {
        const double p2 = ((2 * l + 1) * x * p1 - l * p0) / (l + 1);
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    mu.push_back(x);
    weight.push_back(2 / ((1 - x * x) * dp * dp));
  }
  P.assign(lmax + 1, std::vector<double>(n_half));
  dP = P;
  d2P = P;
  std::vector<double> a, b, c;
  for (int j = 0; j < n_half; ++j) {
    legendre(lmax, mu[j], a, b, c);
    for (int l = 0; l <= lmax; ++l) P[l][j] = a[l], dP[l][j] = b[l], d2P[l][j] = c[l];
  }
}

RadialSolution solve_radial(int l, const std::vector<double>& r, const std::vector<double>& s) {
  // u_l(r) = -1/(2l+1) [A(r) + B(r)], A = r^-(l+1) int_0^r s r'^(l+2), B = r^l int_r^R s r'^(1-l);
  // both are accumulated as ratios so that no power of r over- or underflows.
  const std::size_t n = s.size();
  std::vector<double> A(n, 0.0), B(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) {
    const double ri = r[i], rm = r[i - 1], h = ri - rm, ql = std::pow(rm / ri, l + 1);
    A[i] = ql * A[i - 1] + 0.5 * h * (s[i - 1] * rm * ql + s[i] * ri);
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    const double ri = r[i], rp = r[i + 1], h = rp - ri;
    if (i == 0 && l > 0) {
      B[0] = 0;
      break;
    }
    const double ql = l == 0 ? 1.0 : std::pow(ri / rp, l);
    B[i] = ql * B[i + 1] + 0.5 * h * (s[i] * ri + s[i + 1] * rp * ql);
  }
  RadialSolution out;
  out.u.resize(n);
  out.du.resize(n);
  const double c = -1.0 / (2 * l + 1);
  for (std::size_t i = 0; i < n; ++i) {
    out.u[i] = c * (A[i] + B[i]);
    out.du[i] = i == 0 ? 0.0 : c * (-(l + 1) * A[i] + l * B[i]) / r[i];
  }
  // du/dr at the centre: zero for l != 1 by regularity; u_1 ~ r there (linear extrapolation).
  if (l == 1 && n > 2) out.du[0] = out.du[1] - (out.du[2] - out.du[1]) * r[1] / (r[2] - r[1]);
  return out;
}

std::vector<double> project_scalar(const LegendreTable& t, int l, const std::vector<double>& f, int nr) {
  const std::size_t nm = t.mu.size();
  std::vector<double> out(nr, 0.0);
  for (int i = 0; i < nr; ++i) {
    double s = 0;
    for (std::size_t j = 0; j < nm; ++j) s += t.weight[j] * f[i * nm + j] * t.P[l][j];
    out[i] = (2 * l + 1) * s;  // the half rule counts both hemispheres: 2 * (2l+1)/2
  }
  return out;
}

std::vector<double> project_m1(const LegendreTable& t, int l, const std::vector<double>& f, int nr) {
  const std::size_t nm = t.mu.size();
  std::vector<double> out(nr, 0.0);
  const double norm = (2.0 * l + 1) / (l * (l + 1.0));
  for (int i = 0; i < nr; ++i) {
    double s = 0;
    for (std::size_t j = 0; j < nm; ++j)
      s += t.weight[j] * f[i * nm + j] * std::sqrt(1 - t.mu[j] * t.mu[j]) * t.dP[l][j];
    out[i] = norm * s;
  }
  return out;
}

}  // namespace remnant::rotstar
