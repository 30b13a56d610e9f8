#pragma once
// Pointwise Valencia hydrodynamics in reference-metric form under CFC, gamma_ij = psi^4 f_ij with a
// diagonal f (Cartesian, cylindrical, spherical). The evolved variables are densitised by
// sqrt(gamma/f) = psi^6 (Montero, Baumgarte & Mueller 2014, PRD 89, 084043; Cheong et al. 2020,
// CQG 37, 145015 (Gmunu)):
//   d_t (psi^6 U) + (1/sqrt f) d_j (sqrt f psi^6 F^j) = psi^6 s,
//   U   = (D, S_i, tau, D Ye),  D = rho W, S_i = rho h W^2 v_i, tau = rho h W^2 - p - D,
//   F^j = U (alpha v^j - beta^j) + alpha p (0, delta^j_i, v^j, 0).
// Everything here is per point and NOT densitised; the caller multiplies by psi^6 and the face
// weights. The magnetic terms are in valencia_mhd.hpp (same structs plus a MagneticState).
#include <algorithm>
#include <array>
#include <cmath>

namespace remnant::grmhd {

// Indices of the conserved components in every cons-like group (cons, cons_rhs, fluxes).
enum ConsIndex : int { kD = 0, kS1 = 1, kS2 = 2, kS3 = 3, kTau = 4, kDYe = 5 };
inline constexpr int kNumCons = 6;

// The CFC 3-metric at one point: gamma_ij = psi^4 f_ii (diagonal), lapse, shift.
struct PointMetric {
  double alpha = 1, psi4 = 1;
  std::array<double, 3> beta{0, 0, 0};
  std::array<double, 3> g_dn{1, 1, 1};  // gamma_ii
  std::array<double, 3> g_up{1, 1, 1};  // gamma^ii
};

inline PointMetric point_metric(double psi, double alpha, const std::array<double, 3>& beta,
                                const std::array<double, 3>& f_diag) {
  PointMetric m;
  m.alpha = alpha;
  const double p2 = psi * psi;
  m.psi4 = p2 * p2;
  m.beta = beta;
  for (int i = 0; i < 3; ++i) {
    m.g_dn[i] = m.psi4 * f_diag[i];
    m.g_up[i] = 1.0 / m.g_dn[i];
  }
  return m;
}

// Cartesian coordinates (f = identity): one division instead of three.
inline PointMetric point_metric_cartesian(double psi, double alpha, const std::array<double, 3>& beta) {
  PointMetric m;
  m.alpha = alpha;
  const double p2 = psi * psi;
  m.psi4 = p2 * p2;
  m.beta = beta;
  const double inv = 1.0 / m.psi4;
  m.g_dn = {m.psi4, m.psi4, m.psi4};
  m.g_up = {inv, inv, inv};
  return m;
}

// The fluid state at a point with everything the fluxes need.
struct FluidState {
  double rho = 0, press = 0, eps = 0, h = 1, cs2 = 0, ye = 0;
  double W = 1;
  std::array<double, 3> v{0, 0, 0};     // v^i
  std::array<double, 3> v_dn{0, 0, 0};  // v_i
  double v2 = 0;
};

// Velocity from u^i / u^0-free variables: given W v^i (what is reconstructed), sets W, v^i, v_i, v^2.
inline void set_velocity_from_wv(FluidState& s, const PointMetric& m, double wv0, double wv1, double wv2) {
  const double u2 = m.g_dn[0] * wv0 * wv0 + m.g_dn[1] * wv1 * wv1 + m.g_dn[2] * wv2 * wv2;
  s.W = std::sqrt(1.0 + u2);
  const double iW = 1.0 / s.W;
  s.v = {wv0 * iW, wv1 * iW, wv2 * iW};
  for (int i = 0; i < 3; ++i) s.v_dn[i] = m.g_dn[i] * s.v[i];
  s.v2 = u2 * iW * iW;
}

inline void conserved(const FluidState& s, double* u) {
  const double D = s.rho * s.W;
  const double z = s.rho * s.h * s.W * s.W;
  u[kD] = D;
  u[kS1] = z * s.v_dn[0];
  u[kS2] = z * s.v_dn[1];
  u[kS3] = z * s.v_dn[2];
  u[kTau] = z - s.press - D;
  u[kDYe] = D * s.ye;
}

// Physical flux along direction d given the conserved vector u of the same state.
inline void flux(int d, const FluidState& s, const PointMetric& m, const double* u, double* f) {
  const double vt = m.alpha * s.v[d] - m.beta[d];  // transport velocity
  const double ap = m.alpha * s.press;
  for (int c = 0; c < kNumCons; ++c) f[c] = u[c] * vt;
  f[kS1 + d] += ap;
  f[kTau] += ap * s.v[d];
}

// Characteristic speeds along d (Banyuls et al. 1997, ApJ 476, 221), coordinate velocities.
// `cs2` is the squared signal speed in the fluid frame: the sound speed here, the fast-magnetosonic
// estimate in valencia_mhd.hpp.
inline void characteristic_speeds_with(int d, double cs2, const FluidState& s, const PointMetric& m, double& lm,
                                       double& lp) {
  const double v2 = s.v2, vd = s.v[d];
  const double den = 1.0 / (1.0 - v2 * cs2);
  const double disc = (1.0 - v2) * (m.g_up[d] * (1.0 - v2 * cs2) - vd * vd * (1.0 - cs2));
  const double root = std::sqrt(cs2 * std::max(disc, 0.0));
  const double a = vd * (1.0 - cs2);
  lm = m.alpha * (a - root) * den - m.beta[d];
  lp = m.alpha * (a + root) * den - m.beta[d];
}
inline void characteristic_speeds(int d, const FluidState& s, const PointMetric& m, double& lm, double& lp) {
  characteristic_speeds_with(d, s.cs2, s, m, lm, lp);
}

// HLL (Harten, Lax & van Leer 1983) with the two-wave speeds bounded by zero, for N components.
template <int N>
inline void hll_flux_n(const double* uL, const double* uR, const double* fL, const double* fR, double lmL, double lpL,
                       double lmR, double lpR, double* f) {
  const double lp = std::max({0.0, lpL, lpR});
  const double lm = std::min({0.0, lmL, lmR});
  const double width = lp - lm;
  if (!(width > 1e-300)) {
    for (int c = 0; c < N; ++c) f[c] = 0.5 * (fL[c] + fR[c]);
    return;
  }
  const double iw = 1.0 / width, lpm = lp * lm;
  for (int c = 0; c < N; ++c) f[c] = (lp * fL[c] - lm * fR[c] + lpm * (uR[c] - uL[c])) * iw;
}
inline void hll_flux(const double* uL, const double* uR, const double* fL, const double* fR, double lmL, double lpL,
                     double lmR, double lpR, double* f) {
  hll_flux_n<kNumCons>(uL, uR, fL, fR, lmL, lpL, lmR, lpR, f);
}

}  // namespace remnant::grmhd
