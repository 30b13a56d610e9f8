#pragma once
// The hydro face loop of a line sweep in direction D (a template parameter): from the reconstructed
// states (L.left / L.right) and the face metric (L.face) to the HLL flux densities psi^6 F in
// L.flux. The pointwise functions of valencia.hpp and face_thermo.hpp written out over arrays of
// faces with the same operations in the same order (so the same bits), without branches or calls in
// the main loop, which the compiler vectorises. Tabulated EOS: the table calls come first, in a
// loop of their own (face_thermo_line).
#include "GRMHD/face_thermo.hpp"
#include "GRMHD/valencia.hpp"
#include "line_scratch.hpp"

namespace remnant::grmhd {

// The side states' thermodynamics as work arrays (side 0: left, 1: right).
enum FaceWork : int { kWorkPress = 0, kWorkH = 2, kWorkCs2 = 4, kWorkYe = 6 };

// Non-ideal-gas EOS: press (the reconstructed one), h, cs2 and the clamped Ye of both sides of every
// face, one table call each (complete_face_thermo).
template <class E, int NumRec, int NumFlux>
inline void face_thermo_line(const E& eos, int n, LineScratch<NumRec, NumFlux>& L) {
  for (int side = 0; side < 2; ++side) {
    double* const* st = side == 0 ? L.left : L.right;
    for (int f = 0; f <= n; ++f) {
      FluidState s;
      s.rho = st[kRecRho][f];
      s.ye = st[kRecYe][f];
      complete_face_thermo(eos, s, st[kRecThermal][f], st[kRecPress][f]);
      L.work[kWorkPress + side][f] = s.press;
      L.work[kWorkH + side][f] = s.h;
      L.work[kWorkCs2 + side][f] = s.cs2;
      L.work[kWorkYe + side][f] = s.ye;
    }
  }
}

// One side of a face: the state, its conserved vector u, flux f and speeds lm, lp (the bits of
// set_velocity_from_wv, complete_face_thermo (ideal gas), conserved, flux, characteristic_speeds).
struct SideState {
  double W, v[3], v_dn[3], v2, press, h, cs2, ye;
};

template <int D>
[[gnu::always_inline]] inline void side_flux(const SideState& s, double rho, double alpha, double beta_d, double g_up_d, double* u, double* fl,
                      double& lm, double& lp) {
  const double Dd = rho * s.W;
  const double z = rho * s.h * s.W * s.W;
  u[kD] = Dd;
  u[kS1] = z * s.v_dn[0];
  u[kS2] = z * s.v_dn[1];
  u[kS3] = z * s.v_dn[2];
  u[kTau] = z - s.press - Dd;
  u[kDYe] = Dd * s.ye;
  const double vt = alpha * s.v[D] - beta_d;
  const double ap = alpha * s.press;
#pragma GCC unroll 9
  for (int c = 0; c < kNumCons; ++c) fl[c] = u[c] * vt;
  fl[kS1 + D] += ap;
  fl[kTau] += ap * s.v[D];
  const double cs2 = s.cs2, v2 = s.v2, vd = s.v[D];
  const double den = 1.0 / (1.0 - v2 * cs2);
  const double disc = (1.0 - v2) * (g_up_d * (1.0 - v2 * cs2) - vd * vd * (1.0 - cs2));
  const double root = std::sqrt(cs2 * (disc < 0.0 ? 0.0 : disc));  // std::max(disc, 0.0)
  const double a = vd * (1.0 - cs2);
  lm = alpha * (a - root) * den - beta_d;
  lp = alpha * (a + root) * den - beta_d;
}

// The velocity part of a side state from W v^i and the face metric.
[[gnu::always_inline]] inline void side_velocity(SideState& s, const double* g_dn, double wv0, double wv1, double wv2) {
  const double u2 = g_dn[0] * wv0 * wv0 + g_dn[1] * wv1 * wv1 + g_dn[2] * wv2 * wv2;
  s.W = std::sqrt(1.0 + u2);
  const double iW = 1.0 / s.W;
  s.v[0] = wv0 * iW;
  s.v[1] = wv1 * iW;
  s.v[2] = wv2 * iW;
#pragma GCC unroll 9
  for (int i = 0; i < 3; ++i) s.v_dn[i] = g_dn[i] * s.v[i];
  s.v2 = u2 * iW * iW;
}

// Ideal gas: p, eps, h, cs2 in closed form from the reconstructed pressure.
[[gnu::always_inline]] inline void side_ideal_gas(SideState& s, double gamma, double rho, double thermal) {
  const double p = thermal < 0.0 ? 0.0 : thermal;  // std::max(thermal, 0.0)
  const double p_over_rho = p / rho;
  s.press = p;
  const double eps = p_over_rho / (gamma - 1.0);
  s.h = 1.0 + gamma * eps;
  s.cs2 = gamma * p_over_rho / s.h;
}

// HLL of hll_flux_n with its degenerate-width branch as a select.
template <int N>
[[gnu::always_inline]] inline void hll_select(const double* uL, const double* uR, const double* fL, const double* fR, double lmL, double lpL,
                       double lmR, double lpR, double* f) {
  // std::max({0.0, lpL, lpR}) and std::min({0.0, lmL, lmR}): the first extreme value wins.
  double lp = 0.0, lm = 0.0;
  lp = lp < lpL ? lpL : lp;
  lp = lp < lpR ? lpR : lp;
  lm = lmL < lm ? lmL : lm;
  lm = lmR < lm ? lmR : lm;
  const double width = lp - lm;
  const bool degenerate = !(width > 1e-300);
  const double iw = 1.0 / width, lpm = lp * lm;
#pragma GCC unroll 9
  for (int c = 0; c < N; ++c) {
    const double hll = (lp * fL[c] - lm * fR[c] + lpm * (uR[c] - uL[c])) * iw;
    const double mean = 0.5 * (fL[c] + fR[c]);
    f[c] = degenerate ? mean : hll;
  }
}

template <int D, class E, int NumRec, int NumFlux>
inline void hydro_face_fluxes(const E& eos, int n, LineScratch<NumRec, NumFlux>& L) {
  constexpr bool ideal = reconstructs_pressure<E>;
  [[maybe_unused]] double gamma = 0.0;
  if constexpr (ideal) gamma = eos.gamma();
  else face_thermo_line(eos, n, L);
  const FaceMetricLine& fm = L.face;
#pragma GCC ivdep
  for (int f = 0; f <= n; ++f) {
    const double g_dn[3] = {fm.g_dn[0][f], fm.g_dn[1][f], fm.g_dn[2][f]};
    const double alpha = fm.alpha[f], beta_d = fm.beta[D][f], g_up_d = fm.g_up_d[f];
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
    double ul[kNumCons], ur[kNumCons], fl[kNumCons], fr[kNumCons], fh[kNumCons];
    double lml, lpl, lmr, lpr;
    side_flux<D>(sl, rl, alpha, beta_d, g_up_d, ul, fl, lml, lpl);
    side_flux<D>(sr, rr, alpha, beta_d, g_up_d, ur, fr, lmr, lpr);
    hll_select<kNumCons>(ul, ur, fl, fr, lml, lpl, lmr, lpr, fh);
    const double psi6 = fm.psi6[f];
#pragma GCC unroll 9
    for (int c = 0; c < kNumCons; ++c) L.flux[c][f] = fh[c] * psi6;
  }
}

}  // namespace remnant::grmhd
