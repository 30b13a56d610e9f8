#pragma once
// The MHD face loop of a line sweep in direction D: face_kernel.hpp's hydro loop with the magnetic
// terms of valencia_mhd.hpp (magnetic_state, conserved_mhd, flux_mhd, fast_speed2, the nine-component
// HLL) written out over arrays of faces with the same operations in the same order. Outputs: the
// hydro fluxes psi^6 F (momentum fluxes times the line's flux weights) in L.flux[0..5] and the
// Riemann data of the edge EMFs (mhd_groups.hpp's CtComponent order) in L.flux[6..11].
#include "GRMHD/valencia_mhd.hpp"
#include "face_kernel.hpp"
#include "mhd_groups.hpp"

namespace remnant::grmhd {

// rho, W v^1..3, thermal, Ye, B^{next}, B^{prev} (orthonormal components in curvilinear coordinates).
inline constexpr int kNumRecMhd = kNumRecHydro + 2;
inline constexpr int kRecBNext = kNumRecHydro, kRecBPrev = kNumRecHydro + 1;
inline constexpr int kNumFluxMhd = kNumCons + kNumCt;
using MhdLineScratch = LineScratch<kNumRecMhd, kNumFluxMhd>;
// Work arrays of the MHD loop after face_kernel.hpp's thermodynamics (0..7): the normal field B^D at
// the face and the inverse scale factors of the transverse components (1 in Cartesian coordinates).
enum MhdFaceWork : int { kWorkBNormal = 8, kWorkInvNext = 9, kWorkInvPrev = 10 };

template <int D>
[[gnu::always_inline]] inline void side_flux_mhd(const SideState& s, double rho, double alpha, const double* beta, double g_up_d,
                          const double* g_dn, const double* B, double* u, double* fl, double& lm, double& lp) {
  // magnetic_state
  double B_dn[3];
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) B_dn[i] = g_dn[i] * B[i];
  const double B2 = B[0] * B_dn[0] + B[1] * B_dn[1] + B[2] * B_dn[2];
  const double Bv = B[0] * s.v_dn[0] + B[1] * s.v_dn[1] + B[2] * s.v_dn[2];
  const double b2 = B2 * (1.0 - s.v2) + Bv * Bv;
  // conserved_mhd
  const double Dd = rho * s.W;
  const double z = rho * s.h * s.W * s.W;
  const double zb = z + B2;
  u[kD] = Dd;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) u[kS1 + i] = zb * s.v_dn[i] - Bv * B_dn[i];
  u[kTau] = z - s.press + 0.5 * B2 * (1.0 + s.v2) - 0.5 * Bv * Bv - Dd;
  u[kDYe] = Dd * s.ye;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) u[kB1 + i] = B[i];
  // flux_mhd
  const double vt = alpha * s.v[D] - beta[D];
  const double ap = alpha * (s.press + 0.5 * b2);
  const double Bd = B[D];
#pragma GCC unroll 9
  for (int c = 0; c < kNumCons; ++c) fl[c] = u[c] * vt;
  const double iW2 = 1.0 - s.v2;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) fl[kS1 + i] -= alpha * ((B_dn[i] * iW2 + Bv * s.v_dn[i]) * Bd);
  fl[kS1 + D] += ap;
  fl[kTau] += ap * s.v[D] - alpha * (Bv * Bd);
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) fl[kB1 + i] = B[i] * vt - Bd * (alpha * s.v[i] - beta[i]);
  fl[kB1 + D] = 0.0;
  // fast_speed2, characteristic_speeds_with
  const double va2 = b2 / (rho * s.h + b2);
  const double cs2 = s.cs2 + va2 - s.cs2 * va2;
  const double v2 = s.v2, vd = s.v[D];
  const double den = 1.0 / (1.0 - v2 * cs2);
  const double disc = (1.0 - v2) * (g_up_d * (1.0 - v2 * cs2) - vd * vd * (1.0 - cs2));
  const double root = std::sqrt(cs2 * (disc < 0.0 ? 0.0 : disc));
  const double a = vd * (1.0 - cs2);
  lm = alpha * (a - root) * den - beta[D];
  lp = alpha * (a + root) * den - beta[D];
}

// flux_weight: the momentum-flux factors of the line (mhd_fluxes.cpp's momentum_flux_weights).
template <int D, class E>
inline void mhd_face_fluxes(const E& eos, int n, const std::array<double, 3>& flux_weight, MhdLineScratch& L) {
  constexpr int next = (D + 1) % 3, prev = (D + 2) % 3;
  constexpr bool ideal = reconstructs_pressure<E>;
  [[maybe_unused]] double gamma = 0.0;
  if constexpr (ideal) gamma = eos.gamma();
  else face_thermo_line(eos, n, L);
  const FaceMetricLine& fm = L.face;
  const double w0 = flux_weight[0], w1 = flux_weight[1], w2 = flux_weight[2];
#pragma GCC ivdep
  for (int f = 0; f <= n; ++f) {
    const double g_dn[3] = {fm.g_dn[0][f], fm.g_dn[1][f], fm.g_dn[2][f]};
    const double beta[3] = {fm.beta[0][f], fm.beta[1][f], fm.beta[2][f]};
    const double alpha = fm.alpha[f], g_up_d = fm.g_up_d[f], psi6 = fm.psi6[f];
    SideState sl, sr;
    side_velocity(sl, g_dn, L.left[kRecWv1][f], L.left[kRecWv1 + 1][f], L.left[kRecWv1 + 2][f]);
    side_velocity(sr, g_dn, L.right[kRecWv1][f], L.right[kRecWv1 + 1][f], L.right[kRecWv1 + 2][f]);
    const double rl = L.left[kRecRho][f], rr = L.right[kRecRho][f];
    if constexpr (ideal) {
      side_ideal_gas(sl, gamma, rl, L.left[kRecThermal][f]);
      side_ideal_gas(sr, gamma, rr, L.right[kRecThermal][f]);
      sl.ye = L.left[kRecYe][f];
      sr.ye = L.right[kRecYe][f];
    } else {
      sl.press = L.work[kWorkPress][f], sr.press = L.work[kWorkPress + 1][f];
      sl.h = L.work[kWorkH][f], sr.h = L.work[kWorkH + 1][f];
      sl.cs2 = L.work[kWorkCs2][f], sr.cs2 = L.work[kWorkCs2 + 1][f];
      sl.ye = L.work[kWorkYe][f], sr.ye = L.work[kWorkYe + 1][f];
    }
    const double in = L.work[kWorkInvNext][f], ip = L.work[kWorkInvPrev][f];
    double Bl[3], Br[3];
    Bl[D] = Br[D] = L.work[kWorkBNormal][f];
    Bl[next] = L.left[kRecBNext][f] * in;
    Br[next] = L.right[kRecBNext][f] * in;
    Bl[prev] = L.left[kRecBPrev][f] * ip;
    Br[prev] = L.right[kRecBPrev][f] * ip;
    double ul[kNumMhd], ur[kNumMhd], fl[kNumMhd], fr[kNumMhd], fh[kNumMhd];
    double lml, lpl, lmr, lpr;
    side_flux_mhd<D>(sl, rl, alpha, beta, g_up_d, g_dn, Bl, ul, fl, lml, lpl);
    side_flux_mhd<D>(sr, rr, alpha, beta, g_up_d, g_dn, Br, ur, fr, lmr, lpr);
    hll_select<kNumMhd>(ul, ur, fl, fr, lml, lpl, lmr, lpr, fh);
    fh[kS1] *= w0;
    fh[kS2] *= w1;
    fh[kS3] *= w2;
#pragma GCC unroll 9
    for (int c = 0; c < kNumCons; ++c) L.flux[c][f] = fh[c] * psi6;
    double ap = 0.0, am = 0.0;  // std::max({0.0, lpl, lpr}), std::min({0.0, lml, lmr})
    ap = ap < lpl ? lpl : ap;
    ap = ap < lpr ? lpr : ap;
    am = lml < am ? lml : am;
    am = lmr < am ? lmr : am;
    L.flux[kNumCons + kAlphaPlus][f] = ap;
    L.flux[kNumCons + kAlphaMinus][f] = -am;
    L.flux[kNumCons + kVtLeft][f] = alpha * sl.v[D] - beta[D];
    L.flux[kNumCons + kVtRight][f] = alpha * sr.v[D] - beta[D];
    L.flux[kNumCons + kFluxNext][f] = fh[kB1 + next] * psi6;
    L.flux[kNumCons + kFluxPrev][f] = fh[kB1 + prev] * psi6;
  }
}

}  // namespace remnant::grmhd
