// The atmosphere state: the paper's polytropic values for analytic EOS, beta-equilibrium Ye at T_min
// for tabulated EOS, and the per-cell test and set.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "remnant_test/shared_tables.hpp"
#include "Atmosphere/make_atmosphere.hpp"
#include "EOS/readers.hpp"
#include "EOS/units.hpp"

namespace atmo = remnant::atmosphere;
namespace eos = remnant::eos;

namespace {

using remnant::test::shared_eos;

struct Prim {
  double rho = 1, v[3] = {0.1, 0.2, 0.3}, W = 2, eps = 1, press = 1, T = 1, ye = 0.2, cs2 = 0.1, B[3] = {1, 2, 3};
};

}  // namespace

TEST(Atmosphere, DefaultsAreThePapers) {
  const atmo::AtmosphereConfig c;
  EXPECT_EQ(c.rho_thr, 1e-14);
  EXPECT_EQ(c.xi, 0.9);
  EXPECT_EQ(c.poly_K, 100.0);
  EXPECT_EQ(c.poly_gamma, 2.0);
}

TEST(Atmosphere, PolytropicValuesForAnIdealGas) {
  eos::IdealGas<> gas(5.0 / 3.0);
  atmo::AtmosphereConfig c;
  c.poly_gamma = 1.8;
  const atmo::Atmosphere a = atmo::make_atmosphere(gas, c);
  const double rho = 0.9e-14, K = 100, G = 1.8;
  EXPECT_DOUBLE_EQ(a.rho, rho);
  EXPECT_DOUBLE_EQ(a.press, K * std::pow(rho, G));
  EXPECT_DOUBLE_EQ(a.eps, K * std::pow(rho, G - 1) / (G - 1));
  // cs2 = Gamma p / (rho h) for the polytrope, the paper's closed form.
  const double h = 1 + a.eps + a.press / rho;
  EXPECT_NEAR(a.cs2, G * a.press / (rho * h), 1e-12 * a.cs2);
  // T follows from eps through the simulation's EOS.
  EXPECT_NEAR(a.T, gas.temperature(rho, a.eps, a.ye).T, 1e-15);
  EXPECT_EQ(a.ye, 0.5);
  EXPECT_EQ(a.ye_source, atmo::YeSource::parameter);
}

TEST(Atmosphere, ColdPolytropeHasZeroTemperature) {
  eos::Polytrope<> poly(100.0, 2.0);
  const atmo::Atmosphere a = atmo::make_atmosphere(poly, {});
  EXPECT_EQ(a.T, 0.0);
  EXPECT_DOUBLE_EQ(a.press, poly.press(a.rho));  // same K, Gamma as the EOS here
}

TEST(Atmosphere, TabulatedUsesBetaEquilibriumAtTmin) {
  // The CompOSE file has the electron chemical potential of the CompOSE manual (mu_l - mu_q).
  const std::string path = shared_eos("SFHo_reduced_39r_39t_20y_compose.h5");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "EOS table not found: " << path;
  eos::Tabulated<> t(eos::load_table(path));
  atmo::AtmosphereConfig c;
  c.rho_thr = 1e-10;  // inside the table (rho_min ~ 2.7e-15)
  const atmo::Atmosphere a = atmo::make_atmosphere(t, c);
  EXPECT_EQ(a.T, t.bounds().T_min);
  EXPECT_DOUBLE_EQ(a.rho, 0.9e-10);
  ASSERT_EQ(a.ye_source, atmo::YeSource::beta_equilibrium);
  EXPECT_GT(a.ye, t.bounds().ye_min);
  EXPECT_LT(a.ye, t.bounds().ye_max);
  EXPECT_LT(std::abs(t.mu_nu(a.rho, a.T, a.ye)), 1e-8);
  const eos::Thermo th = t.thermo(a.rho, a.T, a.ye);
  EXPECT_EQ(a.eps, th.eps);
  EXPECT_EQ(a.press, th.press);
  EXPECT_EQ(a.cs2, th.cs2);
  // Through the shared EOS handle: the same.
  const eos::EOS handle{eos::Tabulated<>(t)};
  EXPECT_EQ(atmo::make_atmosphere(handle, c).ye, a.ye);
}

TEST(Atmosphere, CellTestAndSet) {
  atmo::Atmosphere a;
  EXPECT_TRUE(a.is_atmosphere(0.5e-14));
  EXPECT_FALSE(a.is_atmosphere(1e-14));
  EXPECT_TRUE(a.is_atmosphere(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_TRUE(a.is_atmosphere(-1.0));
  a.eps = 3, a.press = 4, a.T = 5, a.ye = 0.45, a.cs2 = 0.01;
  Prim p;
  a.set(p);
  EXPECT_EQ(p.rho, a.rho);
  EXPECT_EQ(p.v[0], 0.0);
  EXPECT_EQ(p.v[2], 0.0);
  EXPECT_EQ(p.W, 1.0);
  EXPECT_EQ(p.eps, 3.0);
  EXPECT_EQ(p.press, 4.0);
  EXPECT_EQ(p.T, 5.0);
  EXPECT_EQ(p.ye, 0.45);
  EXPECT_EQ(p.cs2, 0.01);
  EXPECT_EQ(p.B[1], 2.0);  // B is kept
}

TEST(Atmosphere, RejectsInvalidSettings) {
  eos::IdealGas<> gas(2.0);
  atmo::AtmosphereConfig c;
  c.xi = 1.5;
  EXPECT_THROW(atmo::make_atmosphere(gas, c), std::invalid_argument);
  c = {};
  c.rho_thr = 0;
  EXPECT_THROW(atmo::make_atmosphere(gas, c), std::invalid_argument);
}

// The magnetisation cap: rho rises to b^2 / sigma_max only where the field exceeds it.
TEST(Atmosphere, MagnetisationCap) {
  remnant::atmosphere::Atmosphere a;
  a.rho = 1e-10;
  a.sigma_max = 100;
  struct P {
    double rho = 0, W = 1, eps = 0, press = 0, T = 0, ye = 0, cs2 = 0;
    double v[3] = {0, 0, 0};
  } p;
  a.set(p);
  EXPECT_FALSE(a.limit_magnetisation(p, 1e-9));  // b^2/rho = 10
  EXPECT_EQ(p.rho, 1e-10);
  EXPECT_TRUE(a.limit_magnetisation(p, 1e-4));   // b^2/rho = 1e6
  EXPECT_DOUBLE_EQ(p.rho, 1e-6);
}
