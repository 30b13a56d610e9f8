#pragma once
// Pointwise ideal GRMHD in the Valencia reference-metric form under CFC: the magnetic terms that
// valencia.hpp's hydrodynamics lacks (Anton et al. 2006, ApJ 637, 296; Del Zanna et al. 2007,
// A&A 473, 11). B^i is the Eulerian field in Heaviside-Lorentz units with sqrt(4 pi) absorbed, as
// Con2Prim (state.hpp, prim_to_cons.hpp), whose conserved variables these must reproduce:
//   b^0 = W (B.v) / alpha,  b_i = B_i / W + W (B.v) v_i,  b^2 = B^2 / W^2 + (B.v)^2,
//   S_i = (rho h W^2 + B^2) v_i - (B.v) B_i,  tau = rho h W^2 - p + B^2 (1 + v^2)/2 - (B.v)^2/2 - D,
//   F^d(S_i) = S_i vt^d + alpha (p_tot delta^d_i - b_i B^d / W),  vt = alpha v - beta,
//   F^d(tau) = tau vt^d + alpha (p_tot v^d - (B.v) B^d),  p_tot = p + b^2 / 2,
//   F^d(B^i) = B^i vt^d - B^d vt^i   (the induction flux; its d-component is zero).
// Not densitised, as valencia.hpp. With B = 0 every function returns the bits of its hydro twin
// (the magnetic terms are added as exact zeros in the same order of operations).
#include <algorithm>
#include <array>

#include "GRMHD/valencia.hpp"

namespace remnant::grmhd {

// The magnetic components follow the hydro ones in the MHD state vector of a face Riemann problem.
enum MhdIndex : int { kB1 = kNumCons, kB2 = kNumCons + 1, kB3 = kNumCons + 2 };
inline constexpr int kNumMhd = kNumCons + 3;

// The field at a point and what the fluxes and sources need of it.
struct MagneticState {
  std::array<double, 3> B{0, 0, 0};     // B^i
  std::array<double, 3> B_dn{0, 0, 0};  // B_i
  double B2 = 0;                        // B^i B_i
  double Bv = 0;                        // B^i v_i
  double b2 = 0;                        // b^mu b_mu
};

// Needs s.v_dn and s.v2 consistent with s.W (set_velocity_from_wv or equivalent) and the metric.
inline MagneticState magnetic_state(const FluidState& s, const PointMetric& m, double B1, double B2, double B3) {
  MagneticState g;
  g.B = {B1, B2, B3};
  for (int i = 0; i < 3; ++i) g.B_dn[i] = m.g_dn[i] * g.B[i];
  g.B2 = g.B[0] * g.B_dn[0] + g.B[1] * g.B_dn[1] + g.B[2] * g.B_dn[2];
  g.Bv = g.B[0] * s.v_dn[0] + g.B[1] * s.v_dn[1] + g.B[2] * s.v_dn[2];
  g.b2 = g.B2 * (1.0 - s.v2) + g.Bv * g.Bv;  // 1/W^2 = 1 - v^2: no division in the face loop
  return g;
}

// The spatial projection of b^mu, gamma^i_mu b^mu = B^i / W + W (B.v) v^i.
inline std::array<double, 3> spatial_b(const FluidState& s, const MagneticState& g) {
  const double iW = 1.0 / s.W, wbv = s.W * g.Bv;
  return {g.B[0] * iW + wbv * s.v[0], g.B[1] * iW + wbv * s.v[1], g.B[2] * iW + wbv * s.v[2]};
}

inline void conserved_mhd(const FluidState& s, const MagneticState& g, double* u) {
  const double D = s.rho * s.W;
  const double z = s.rho * s.h * s.W * s.W;
  const double zb = z + g.B2;
  u[kD] = D;
  for (int i = 0; i < 3; ++i) u[kS1 + i] = zb * s.v_dn[i] - g.Bv * g.B_dn[i];
  u[kTau] = z - s.press + 0.5 * g.B2 * (1.0 + s.v2) - 0.5 * g.Bv * g.Bv - D;
  u[kDYe] = D * s.ye;
  for (int i = 0; i < 3; ++i) u[kB1 + i] = g.B[i];
}

// Physical flux along d of the nine components, given the conserved vector u of the same state.
inline void flux_mhd(int d, const FluidState& s, const MagneticState& g, const PointMetric& m, const double* u,
                     double* f) {
  const double vt = m.alpha * s.v[d] - m.beta[d];
  const double ap = m.alpha * (s.press + 0.5 * g.b2);  // alpha p_tot
  const double Bd = g.B[d];
  for (int c = 0; c < kNumCons; ++c) f[c] = u[c] * vt;
  // b_i / W = B_i / W^2 + (B.v) v_i
  const double iW2 = 1.0 - s.v2;
  for (int i = 0; i < 3; ++i) f[kS1 + i] -= m.alpha * ((g.B_dn[i] * iW2 + g.Bv * s.v_dn[i]) * Bd);
  f[kS1 + d] += ap;
  f[kTau] += ap * s.v[d] - m.alpha * (g.Bv * Bd);
  for (int i = 0; i < 3; ++i) f[kB1 + i] = g.B[i] * vt - Bd * (m.alpha * s.v[i] - m.beta[i]);
  f[kB1 + d] = 0.0;
}

// The squared fast-magnetosonic speed estimate in the fluid frame, a^2 = cs^2 + va^2 - cs^2 va^2 with
// va^2 = b^2 / (rho h + b^2) (Gammie et al. 2003; Del Zanna et al. 2007): exact for propagation
// normal to b, an upper bound otherwise.
inline double fast_speed2(const FluidState& s, const MagneticState& g) {
  const double va2 = g.b2 / (s.rho * s.h + g.b2);
  return s.cs2 + va2 - s.cs2 * va2;
}

inline void characteristic_speeds_mhd(int d, const FluidState& s, const MagneticState& g, const PointMetric& m,
                                      double& lm, double& lp) {
  characteristic_speeds_with(d, fast_speed2(s, g), s, m, lm, lp);
}

}  // namespace remnant::grmhd
