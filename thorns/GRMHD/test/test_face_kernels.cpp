// The vectorised face loops of the line sweeps (src/face_kernel.hpp, src/face_kernel_mhd.hpp) must give
// the bits of the pointwise functions they write out (valencia.hpp, valencia_mhd.hpp, face_thermo.hpp,
// hll_flux_n): random left/right states in a random diagonal CFC metric, every direction, the ideal gas
// (closed-form thermodynamics in the loop) and a polytrope (the EOS calls in their own loop), with a
// negative reconstructed pressure and a face whose HLL width is zero among them. Compared bit for bit.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <random>

#include "EOS/ideal_gas.hpp"
#include "EOS/polytrope.hpp"
#include "GRMHD/face_thermo.hpp"
#include "GRMHD/valencia_mhd.hpp"
#include "face_kernel_mhd.hpp"

namespace {

using namespace remnant::grmhd;
using remnant::Point3;

constexpr int kFaces = 17;  // n = 16 cells: faces 0..16

// Random states and metric on the faces of L; the metric factors (psi, f_ii) are returned for the
// pointwise reference. Face 0: two equal states at rest with zero pressure and shift (HLL width 0);
// face 1: a negative reconstructed pressure (raised into the band around the EOS pressure).
template <class L>
void fill(L& line, int d, std::mt19937_64& rng, std::array<double, kFaces>& psi, std::array<Point3, kFaces>& fd) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int f = 0; f < kFaces; ++f) {
    psi[f] = 1.0 + 0.5 * u(rng);
    fd[f] = {1.0 + u(rng), 0.5 + u(rng), 0.2 + 2.0 * u(rng)};
    const double p2 = psi[f] * psi[f], psi4 = p2 * p2;
    line.face.psi6[f] = p2 * p2 * p2;
    line.face.alpha[f] = 0.5 + 0.5 * u(rng);
    for (int c = 0; c < 3; ++c) {
      line.face.beta[c][f] = f == 0 ? 0.0 : 0.3 * (u(rng) - 0.5);
      line.face.g_dn[c][f] = psi4 * fd[f][c];
    }
    line.face.g_up_d[f] = 1.0 / line.face.g_dn[d][f];
    for (double* const* side : {line.left, line.right}) {
      side[kRecRho][f] = f == 0 ? 0.5 : 1e-3 + u(rng);
      for (int c = 0; c < 3; ++c) side[kRecWv1 + c][f] = f == 0 ? 0.0 : 2.0 * (u(rng) - 0.5);
      side[kRecThermal][f] = f == 0 ? 0.0 : f == 1 ? -1e-3 : u(rng);
      side[kRecYe][f] = 0.1 + 0.3 * u(rng);
      side[kRecPress][f] = f == 1 ? -1e-3 : u(rng);
    }
  }
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

template <class E>
FluidState reference_state(const E& eos, const PointMetric& pm, double* const* side, int f) {
  FluidState s;
  s.rho = side[kRecRho][f];
  s.ye = side[kRecYe][f];
  set_velocity_from_wv(s, pm, side[kRecWv1][f], side[kRecWv1 + 1][f], side[kRecWv1 + 2][f]);
  complete_face_thermo(eos, s, side[kRecThermal][f], side[kRecPress][f]);
  return s;
}

template <int D, class E>
void check_hydro(const E& eos, std::uint64_t seed) {
  LineScratch<kNumRecHydro, kNumCons> L;
  L.ensure(kFaces - 1, 3);
  std::mt19937_64 rng(seed);
  std::array<double, kFaces> psi;
  std::array<Point3, kFaces> fd;
  fill(L, D, rng, psi, fd);
  hydro_face_fluxes<D>(eos, kFaces - 1, L);
  for (int f = 0; f < kFaces; ++f) {
    const std::array<double, 3> beta{L.face.beta[0][f], L.face.beta[1][f], L.face.beta[2][f]};
    const PointMetric pm = point_metric(psi[f], L.face.alpha[f], beta, fd[f]);
    const FluidState sl = reference_state(eos, pm, L.left, f), sr = reference_state(eos, pm, L.right, f);
    double ul[kNumCons], ur[kNumCons], fl[kNumCons], fr[kNumCons], fh[kNumCons], lml, lpl, lmr, lpr;
    conserved(sl, ul);
    conserved(sr, ur);
    flux(D, sl, pm, ul, fl);
    flux(D, sr, pm, ur, fr);
    characteristic_speeds(D, sl, pm, lml, lpl);
    characteristic_speeds(D, sr, pm, lmr, lpr);
    hll_flux(ul, ur, fl, fr, lml, lpl, lmr, lpr, fh);
    for (int c = 0; c < kNumCons; ++c)
      EXPECT_TRUE(same_bits(L.flux[c][f], fh[c] * L.face.psi6[f]))
          << "direction " << D << " face " << f << " component " << c << ": " << L.flux[c][f] << " vs "
          << fh[c] * L.face.psi6[f];
  }
}

template <int D, class E>
void check_mhd(const E& eos, std::uint64_t seed) {
  constexpr int next = (D + 1) % 3, prev = (D + 2) % 3;
  MhdLineScratch L;
  L.ensure(kFaces - 1, 3);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<double, kFaces> psi;
  std::array<Point3, kFaces> fd;
  fill(L, D, rng, psi, fd);
  for (int f = 0; f < kFaces; ++f) {
    const double scale = f == 0 ? 0.0 : 1.0;  // face 0 unmagnetised: the zero-width HLL
    L.work[kWorkBNormal][f] = scale * u(rng);
    L.work[kWorkInvNext][f] = 1.0 + 0.5 * u(rng);
    L.work[kWorkInvPrev][f] = 1.0 + 0.5 * u(rng);
    for (double* const* side : {L.left, L.right}) {
      side[kRecBNext][f] = scale * u(rng);
      side[kRecBPrev][f] = scale * u(rng);
    }
  }
  const std::array<double, 3> weight{1.0 + 0.1 * u(rng), 1.0 + 0.1 * u(rng), 1.0 + 0.1 * u(rng)};
  mhd_face_fluxes<D>(eos, kFaces - 1, weight, L);
  for (int f = 0; f < kFaces; ++f) {
    const std::array<double, 3> beta{L.face.beta[0][f], L.face.beta[1][f], L.face.beta[2][f]};
    const PointMetric pm = point_metric(psi[f], L.face.alpha[f], beta, fd[f]);
    const FluidState sl = reference_state(eos, pm, L.left, f), sr = reference_state(eos, pm, L.right, f);
    std::array<double, 3> Bl, Br;
    Bl[D] = Br[D] = L.work[kWorkBNormal][f];
    Bl[next] = L.left[kRecBNext][f] * L.work[kWorkInvNext][f];
    Br[next] = L.right[kRecBNext][f] * L.work[kWorkInvNext][f];
    Bl[prev] = L.left[kRecBPrev][f] * L.work[kWorkInvPrev][f];
    Br[prev] = L.right[kRecBPrev][f] * L.work[kWorkInvPrev][f];
    const MagneticState ml = magnetic_state(sl, pm, Bl[0], Bl[1], Bl[2]);
    const MagneticState mr = magnetic_state(sr, pm, Br[0], Br[1], Br[2]);
    double ul[kNumMhd], ur[kNumMhd], fl[kNumMhd], fr[kNumMhd], fh[kNumMhd], lml, lpl, lmr, lpr;
    conserved_mhd(sl, ml, ul);
    conserved_mhd(sr, mr, ur);
    flux_mhd(D, sl, ml, pm, ul, fl);
    flux_mhd(D, sr, mr, pm, ur, fr);
    characteristic_speeds_mhd(D, sl, ml, pm, lml, lpl);
    characteristic_speeds_mhd(D, sr, mr, pm, lmr, lpr);
    hll_flux_n<kNumMhd>(ul, ur, fl, fr, lml, lpl, lmr, lpr, fh);
    for (int j = 0; j < 3; ++j) fh[kS1 + j] *= weight[j];
    const double psi6 = L.face.psi6[f];
    double expect[kNumFluxMhd];
    for (int c = 0; c < kNumCons; ++c) expect[c] = fh[c] * psi6;
    expect[kNumCons + kAlphaPlus] = std::max({0.0, lpl, lpr});
    expect[kNumCons + kAlphaMinus] = -std::min({0.0, lml, lmr});
    expect[kNumCons + kVtLeft] = pm.alpha * sl.v[D] - pm.beta[D];
    expect[kNumCons + kVtRight] = pm.alpha * sr.v[D] - pm.beta[D];
    expect[kNumCons + kFluxNext] = fh[kB1 + next] * psi6;
    expect[kNumCons + kFluxPrev] = fh[kB1 + prev] * psi6;
    for (int c = 0; c < kNumFluxMhd; ++c)
      EXPECT_TRUE(same_bits(L.flux[c][f], expect[c]))
          << "direction " << D << " face " << f << " output " << c << ": " << L.flux[c][f] << " vs " << expect[c];
  }
}

TEST(FaceKernels, HydroIdealGasHasTheBitsOfThePointwiseFunctions) {
  const remnant::eos::IdealGas<> eos(5.0 / 3.0);
  check_hydro<0>(eos, 1);
  check_hydro<1>(eos, 2);
  check_hydro<2>(eos, 3);
}

TEST(FaceKernels, HydroWithEosCallsHasTheBitsOfThePointwiseFunctions) {
  const remnant::eos::Polytrope<> eos(100.0, 2.0);
  check_hydro<0>(eos, 4);
  check_hydro<1>(eos, 5);
  check_hydro<2>(eos, 6);
}

TEST(FaceKernels, MhdHasTheBitsOfThePointwiseFunctions) {
  const remnant::eos::IdealGas<> ideal(2.0);
  check_mhd<0>(ideal, 7);
  check_mhd<1>(ideal, 8);
  check_mhd<2>(ideal, 9);
  const remnant::eos::Polytrope<> poly(100.0, 2.0);
  check_mhd<0>(poly, 10);
  check_mhd<2>(poly, 11);
}

}  // namespace
