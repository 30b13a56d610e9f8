#pragma once
// The hydro face loop of a line sweep in direction D (a template parameter): from the reconstructed
// states (L.left / L.right) and the face metric (L.face) to the HLL flux densities psi^6 F in
// L.flux or a FaceOutput: the pointwise functions of valencia.hpp and face_thermo.hpp, inlined (so the same bits),
// over arrays of faces, with HLL's degenerate-width branch as a select, so that the compiler
// vectorises the loop. Tabulated EOS: the table calls come first, in a
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

// The face metric as the pointwise functions read it (alpha, beta, gamma_ii, gamma^DD; the other
// gamma^ii are not read by the face kernels).
template <int D>
[[gnu::always_inline]] inline PointMetric face_point_metric(const FaceMetricLine& fm, int f) {
  PointMetric m;
  m.alpha = fm.alpha[f];
#pragma GCC unroll 3
  for (int c = 0; c < 3; ++c) {
    m.beta[c] = fm.beta[c][f];
    m.g_dn[c] = fm.g_dn[c][f];
  }
  m.g_up[D] = fm.g_up_d[f];
  return m;
}

// One side (Side 0: left, 1: right) of face f: rho, Ye, W v^i from the reconstructed states, then
// the thermodynamics, in closed form for the ideal gas (complete_face_thermo) or from
// face_thermo_line's work arrays.
template <int Side, class E, int NumRec, int NumFlux>
[[gnu::always_inline]] inline FluidState face_side_state(const E& eos, const PointMetric& m,
                                                         const LineScratch<NumRec, NumFlux>& L, int f) {
  double* const* st = Side == 0 ? L.left : L.right;
  FluidState s;
  s.rho = st[kRecRho][f];
  set_velocity_from_wv(s, m, st[kRecWv1][f], st[kRecWv1 + 1][f], st[kRecWv1 + 2][f]);
  if constexpr (reconstructs_pressure<E>) {
    s.ye = st[kRecYe][f];
    complete_face_thermo(eos, s, st[kRecThermal][f], st[kRecThermal][f]);  // the ideal gas's thermal variable is p (kRecPress is not reconstructed)
  } else {
    s.press = L.work[kWorkPress + Side][f];
    s.h = L.work[kWorkH + Side][f];
    s.cs2 = L.work[kWorkCs2 + Side][f];
    s.ye = L.work[kWorkYe + Side][f];
  }
  return s;
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

// The face loop; flatten: every pointwise function inlined whatever the inliner's budget (a call
// left in the loop stops its vectorisation). always_inline: into the sweeps, which are flattened
// whole (rhs.cpp), so that the AVX2 sweep compiles it for AVX2 (kernel_isa.hpp).
template <int D, class E, int NumRec, int NumFlux, class Out>
[[gnu::always_inline, gnu::flatten]] inline void hydro_face_loop(const E& eos, int n, const LineScratch<NumRec, NumFlux>& L, const Out& out) {
#pragma GCC ivdep
  for (int f = 0; f <= n; ++f) {
    const PointMetric m = face_point_metric<D>(L.face, f);
    const FluidState sl = face_side_state<0>(eos, m, L, f), sr = face_side_state<1>(eos, m, L, f);
    double ul[kNumCons], ur[kNumCons], fl[kNumCons], fr[kNumCons], fh[kNumCons];
    double lml, lpl, lmr, lpr;
    conserved(sl, ul);
    conserved(sr, ur);
    flux(D, sl, m, ul, fl);
    flux(D, sr, m, ur, fr);
    characteristic_speeds(D, sl, m, lml, lpl);
    characteristic_speeds(D, sr, m, lmr, lpr);
    hll_select<kNumCons>(ul, ur, fl, fr, lml, lpl, lmr, lpr, fh);
    const double psi6 = L.face.psi6[f];
#pragma GCC unroll 9
    for (int c = 0; c < kNumCons; ++c) out(c, f) = fh[c] * psi6;
  }
}

// Into `out` (a FaceOutput), or into L.flux.
template <int D, class E, int NumRec, int NumFlux, class Out>
[[gnu::always_inline]] inline void hydro_face_fluxes(const E& eos, int n, LineScratch<NumRec, NumFlux>& L, const Out& out) {
  if constexpr (!reconstructs_pressure<E>) face_thermo_line(eos, n, L);
  hydro_face_loop<D>(eos, n, L, out);
}
template <int D, class E, int NumRec, int NumFlux>
inline void hydro_face_fluxes(const E& eos, int n, LineScratch<NumRec, NumFlux>& L) {
  hydro_face_fluxes<D>(eos, n, L, face_output(L));
}

}  // namespace remnant::grmhd
