// Trilinear interpolation is exact for quantities linear in (ln rho, ln T, Ye).
#include <random>

#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "eos_test_util.hpp"

using namespace remnant::eos;
using eos_test::Synthetic;

namespace {

void expect_reproduces(const Tabulated<CountCalls>& eos, const Synthetic& s, double tol) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 2000; ++k) {
    const double lr = s.lr0 + (s.lr1 - s.lr0) * u(rng), lt = s.lt0 + (s.lt1 - s.lt0) * u(rng);
    const double ye = s.y0 + (s.y1 - s.y0) * u(rng);
    const double rho = std::exp(lr), T = std::exp(lt);
    const Thermo th = eos.thermo(rho, T, ye);
    const double p = std::exp(s.logp(lr, lt, ye)), e = std::exp(s.logeps(lr, lt, ye)) - s.eps_shift;
    EXPECT_NEAR(th.press / p, 1.0, tol);
    EXPECT_NEAR(th.eps / e, 1.0, tol);
    EXPECT_NEAR(th.cs2, s.cs2(lr, lt, ye), tol * std::abs(s.cs2(lr, lt, ye)));
    EXPECT_NEAR(th.entropy, s.s(lr, lt, ye), tol * std::abs(s.s(lr, lt, ye)));
    EXPECT_NEAR(th.h, 1 + e + p / rho, tol);
    const ChemPot mu = eos.chem(rho, T, ye);
    EXPECT_NEAR(mu.mu_e, s.mue(lr, lt, ye), tol * std::abs(s.mue(lr, lt, ye)));
    EXPECT_NEAR(mu.mu_p, s.mup(lr, lt, ye), tol * std::abs(s.mup(lr, lt, ye)));
    EXPECT_NEAR(mu.mu_n, s.mun(lr, lt, ye), tol * std::abs(s.mun(lr, lt, ye)) + 1e-12);
  }
  EXPECT_EQ(eos.counter().count(), 4000u);  // one table evaluation per call
}

}  // namespace

TEST(EOSInterpolation, LinearSyntheticTableIsExact) {
  Synthetic s;
  Tabulated<CountCalls> eos(build_table(s.raw()));
  EXPECT_TRUE(eos.table().report.issues.empty()) << eos.table().report.str();
  expect_reproduces(eos, s, 1e-12);
}

TEST(EOSInterpolation, LinearSyntheticTableThroughStellarCollapseReader) {
  Synthetic s;
  const std::string path = eos_test::temp_path("synthetic_sc.h5");
  eos_test::write_stellarcollapse(path, s.raw(), s.eps_shift * remnant::units::c2_cgs);
  Tabulated<CountCalls> eos(load_table(path));
  EXPECT_EQ(eos.table().format, "StellarCollapse HDF5");
  expect_reproduces(eos, s, 1e-12);
}

TEST(EOSInterpolation, GridPointsAndClampingOutsideTheTable) {
  Synthetic s;
  Tabulated<> eos(build_table(s.raw()));
  const double rho = std::exp(s.lr(3)), T = std::exp(s.lt(4)), ye = s.ye(2);
  EXPECT_NEAR(eos.press(rho, T, ye) / std::exp(s.logp(s.lr(3), s.lt(4), s.ye(2))), 1.0, 1e-13);
  // Outside the table: evaluated at the edge, finite, never NaN.
  const double p_hi = eos.press(1e10, 1e10, 2.0), p_edge = eos.press(std::exp(s.lr1), std::exp(s.lt1), s.y1);
  EXPECT_NEAR(p_hi / p_edge, 1.0, 1e-13);
  EXPECT_TRUE(std::isfinite(eos.press(0.0, 0.0, -1.0)));
  EXPECT_TRUE(std::isfinite(eos.press(std::nan(""), std::nan(""), std::nan(""))));
}

TEST(EOSInterpolation, BoundsOfTheSyntheticTable) {
  Synthetic s;
  Tabulated<> eos(build_table(s.raw()));
  const Bounds& b = eos.bounds();
  EXPECT_NEAR(b.rho_min, std::exp(s.lr0), 1e-15 * std::exp(s.lr0));
  EXPECT_NEAR(b.T_max, std::exp(s.lt1), 1e-12);
  EXPECT_DOUBLE_EQ(b.ye_min, s.y0);
  EXPECT_LE(b.eps_min, b.eps_max);
  // h_min must bound the interpolant from below everywhere.
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0, 1);
  double hmin = 1e300;
  for (int k = 0; k < 20000; ++k) {
    const double rho = std::exp(s.lr0 + (s.lr1 - s.lr0) * u(rng)), T = std::exp(s.lt0 + (s.lt1 - s.lt0) * u(rng));
    hmin = std::min(hmin, eos.thermo(rho, T, s.y0 + (s.y1 - s.y0) * u(rng)).h);
  }
  EXPECT_LE(b.h_min, hmin);
  EXPECT_GT(b.h_min, hmin - 1e-2);
}
