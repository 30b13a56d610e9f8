#pragma once
// The MHD face loop of a line sweep in direction D: face_kernel.hpp's hydro loop (the same side
// states) with the pointwise magnetic functions of valencia_mhd.hpp (magnetic_state, conserved_mhd,
// flux_mhd, characteristic_speeds_mhd) inlined and the nine-component HLL as a select. Outputs: the
// hydro fluxes psi^6 F (momentum fluxes times the line's flux weights) in outputs 0..5 and the
// Riemann data of the edge EMFs (mhd_groups.hpp's CtComponent order) in outputs 6..11 (of L.flux
// or a FaceOutput).
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

// The metric and the left and right fluid and magnetic states at face f of the line (the field's
// normal component from the face, the transverse ones reconstructed).
struct MhdFaceStates {
  PointMetric m;
  FluidState sl, sr;
  MagneticState ml, mr;
};
template <int D, class E>
[[gnu::always_inline]] inline MhdFaceStates mhd_face_states(const E& eos, const MhdLineScratch& L, int f) {
  constexpr int next = (D + 1) % 3, prev = (D + 2) % 3;
  MhdFaceStates st;
  st.m = face_point_metric<D>(L.face, f);
  st.sl = face_side_state<0>(eos, st.m, L, f);
  st.sr = face_side_state<1>(eos, st.m, L, f);
  const double in = L.work[kWorkInvNext][f], ip = L.work[kWorkInvPrev][f];
  double Bl[3], Br[3];
  Bl[D] = Br[D] = L.work[kWorkBNormal][f];
  Bl[next] = L.left[kRecBNext][f] * in;
  Br[next] = L.right[kRecBNext][f] * in;
  Bl[prev] = L.left[kRecBPrev][f] * ip;
  Br[prev] = L.right[kRecBPrev][f] * ip;
  st.ml = magnetic_state(st.sl, st.m, Bl[0], Bl[1], Bl[2]);
  st.mr = magnetic_state(st.sr, st.m, Br[0], Br[1], Br[2]);
  return st;
}

// What the edge EMFs read of face f: alpha^+- (std::max({0, lpl, lpr}), -std::min({0, lml, lmr}))
// and the transport velocities of the two sides.
template <int D, class Out>
[[gnu::always_inline]] inline void write_emf_riemann_data(const Out& out, int f, const MhdFaceStates& st, double lml,
                                                          double lpl, double lmr, double lpr) {
  double ap = 0.0, am = 0.0;
  ap = ap < lpl ? lpl : ap;
  ap = ap < lpr ? lpr : ap;
  am = lml < am ? lml : am;
  am = lmr < am ? lmr : am;
  out(kNumCons + kAlphaPlus, f) = ap;
  out(kNumCons + kAlphaMinus, f) = -am;
  out(kNumCons + kVtLeft, f) = st.m.alpha * st.sl.v[D] - st.m.beta[D];
  out(kNumCons + kVtRight, f) = st.m.alpha * st.sr.v[D] - st.m.beta[D];
}

// flatten, always_inline: as hydro_face_loop. Induction = false: without the induction fluxes (outputs 10, 11 left
// alone; HLL of the six hydro components only, whose operations are the same).
template <int D, bool Induction = true, class E, class Out>
[[gnu::always_inline, gnu::flatten]] inline void mhd_face_loop(const E& eos, int n, const std::array<double, 3>& flux_weight,
                                           const MhdLineScratch& L, const Out& out) {
  constexpr int next = (D + 1) % 3, prev = (D + 2) % 3;
  const double w0 = flux_weight[0], w1 = flux_weight[1], w2 = flux_weight[2];
#pragma GCC ivdep
  for (int f = 0; f <= n; ++f) {
    const MhdFaceStates st = mhd_face_states<D>(eos, L, f);
    const PointMetric& m = st.m;
    const FluidState &sl = st.sl, &sr = st.sr;
    const MagneticState &ml = st.ml, &mr = st.mr;
    const double psi6 = L.face.psi6[f];
    double ul[kNumMhd], ur[kNumMhd], fl[kNumMhd], fr[kNumMhd], fh[kNumMhd];
    double lml, lpl, lmr, lpr;
    conserved_mhd(sl, ml, ul);
    conserved_mhd(sr, mr, ur);
    flux_mhd(D, sl, ml, m, ul, fl);
    flux_mhd(D, sr, mr, m, ur, fr);
    characteristic_speeds_mhd(D, sl, ml, m, lml, lpl);
    characteristic_speeds_mhd(D, sr, mr, m, lmr, lpr);
    hll_select<Induction ? kNumMhd : kNumCons>(ul, ur, fl, fr, lml, lpl, lmr, lpr, fh);
    fh[kS1] *= w0;
    fh[kS2] *= w1;
    fh[kS3] *= w2;
#pragma GCC unroll 9
    for (int c = 0; c < kNumCons; ++c) out(c, f) = fh[c] * psi6;
    write_emf_riemann_data<D>(out, f, st, lml, lpl, lmr, lpr);
    if constexpr (Induction) {
      out(kNumCons + kFluxNext, f) = fh[kB1 + next] * psi6;
      out(kNumCons + kFluxPrev, f) = fh[kB1 + prev] * psi6;
    }
  }
}

// The part of mhd_face_loop that the uct_hll EMFs read (outputs 6..9: alpha^+-, the transport
// velocities), for the lines of the transverse ghost layers, whose fluxes no one reads with uct_hll:
// the same operations for these outputs, without the conserved variables, the fluxes and HLL.
template <int D, class E, class Out>
[[gnu::always_inline, gnu::flatten]] inline void mhd_face_speed_loop(const E& eos, int n, const MhdLineScratch& L, const Out& out) {
#pragma GCC ivdep
  for (int f = 0; f <= n; ++f) {
    const MhdFaceStates st = mhd_face_states<D>(eos, L, f);
    double lml, lpl, lmr, lpr;
    characteristic_speeds_mhd(D, st.sl, st.ml, st.m, lml, lpl);
    characteristic_speeds_mhd(D, st.sr, st.mr, st.m, lmr, lpr);
    write_emf_riemann_data<D>(out, f, st, lml, lpl, lmr, lpr);
  }
}

// flux_weight: the momentum-flux factors of the line (mhd_fluxes.cpp's momentum_flux_weights).
// Into `out` (a FaceOutput), or into L.flux; Induction: as mhd_face_loop.
template <int D, bool Induction = true, class E, class Out>
[[gnu::always_inline]] inline void mhd_face_fluxes(const E& eos, int n, const std::array<double, 3>& flux_weight, MhdLineScratch& L,
                            const Out& out) {
  if constexpr (!reconstructs_pressure<E>) face_thermo_line(eos, n, L);
  mhd_face_loop<D, Induction>(eos, n, flux_weight, L, out);
}
// Only the speeds and transport velocities (mhd_face_speed_loop) into `out`.
template <int D, class E, class Out>
[[gnu::always_inline]] inline void mhd_face_speeds(const E& eos, int n, MhdLineScratch& L, const Out& out) {
  if constexpr (!reconstructs_pressure<E>) face_thermo_line(eos, n, L);
  mhd_face_speed_loop<D>(eos, n, L, out);
}
template <int D, class E>
inline void mhd_face_fluxes(const E& eos, int n, const std::array<double, 3>& flux_weight, MhdLineScratch& L) {
  mhd_face_fluxes<D>(eos, n, flux_weight, L, face_output(L));
}

}  // namespace remnant::grmhd
