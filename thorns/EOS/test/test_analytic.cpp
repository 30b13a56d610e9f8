// Ideal gas, polytrope, hybrid: thermodynamic consistency and inversions.
#include "EOS/eos.hpp"
#include "eos_test_util.hpp"

using namespace remnant::eos;

namespace {

// cs2 h = dp/drho|_s: check against a numerical derivative along an adiabat
// (d eps = p / rho^2 d rho at fixed entropy).
template <class E>
double numerical_cs2(const E& eos, double rho, double eps) {
  const double d = 1e-5 * rho;
  double T = 0;
  const Thermo c = eos.thermo_from_eps(rho, eps, 0.1, T);
  const Thermo up = eos.thermo_from_eps(rho + d, eps + c.press / (rho * rho) * d, 0.1, T);
  const Thermo dn = eos.thermo_from_eps(rho - d, eps - c.press / (rho * rho) * d, 0.1, T);
  return (up.press - dn.press) / (2 * d) / c.h;
}

}  // namespace

TEST(EOSAnalytic, IdealGas) {
  IdealGas<CountCalls> eos(5.0 / 3.0);
  const double rho = 1e-4, T = 10.0;
  const Thermo th = eos.thermo(rho, T, 0.1);
  EXPECT_NEAR(th.press, (5.0 / 3.0 - 1) * rho * th.eps, 1e-18);
  // p = n T with n = rho / m_b.
  EXPECT_NEAR(th.eps, T / ((5.0 / 3.0 - 1) * remnant::units::neutron_mass_MeV), 1e-16);
  EXPECT_NEAR(th.cs2, numerical_cs2(eos, rho, th.eps), 1e-8);
  const Inversion inv = eos.temperature(rho, th.eps, 0.1);
  EXPECT_NEAR(inv.T, T, 1e-12);
  EXPECT_EQ(eos.temperature(rho, -1.0, 0.1).flags & kInvBelowEpsLow, kInvBelowEpsLow);
  EXPECT_GT(eos.counter().count(), 0u);
}

TEST(EOSAnalytic, PolytropeAtmosphereValuesOfThePaper) {
  // K = 100, Gamma = 2: eps = K rho / (Gamma - 1), cs2 = p Gamma (Gamma - 1) / (rho (Gamma - 1) + p Gamma).
  Polytrope<> eos(100.0, 2.0);
  const double rho = 1e-14 * 0.9;
  const Thermo th = eos.thermo(rho);
  const double p = 100 * rho * rho;
  EXPECT_NEAR(th.press / p, 1, 1e-14);
  EXPECT_NEAR(th.eps / (100 * rho), 1, 1e-14);
  EXPECT_NEAR(th.cs2 / (p * 2 * 1 / (rho * 1 + p * 2)), 1, 1e-12);
  double T = 1;
  std::uint32_t f = 0;
  const Thermo again = eos.thermo_from_eps(rho, 5.0, 0.1, T, &f);
  EXPECT_EQ(again.eps, th.eps);
  EXPECT_EQ(f, kInvAboveEpsHigh);
  EXPECT_EQ(T, 0.0);
}

TEST(EOSAnalytic, PiecewisePolytropeIsContinuous) {
  PiecewisePolytrope pp(8.9e-7 * 1e4, {1.357, 3.0, 2.8}, {2e-4, 8e-4});
  for (double rb : {2e-4, 8e-4}) {
    EXPECT_NEAR(pp.press(rb * (1 - 1e-12)) / pp.press(rb * (1 + 1e-12)), 1, 1e-9);
    EXPECT_NEAR(pp.eps(rb * (1 - 1e-12)) / pp.eps(rb * (1 + 1e-12)), 1, 1e-9);
  }
  EXPECT_THROW(PiecewisePolytrope(1.0, {2.0, 3.0}, {}), EosError);
  EXPECT_THROW(PiecewisePolytrope(1.0, {0.9}, {}), EosError);
}

TEST(EOSAnalytic, HybridThermalPartAndCs2) {
  Hybrid<> eos(PiecewisePolytrope(100.0, {2.0}, {}), 1.8);
  const double rho = 1e-3, ec = 100 * rho;
  const double eps = ec * 1.5;
  double T = 0;
  std::uint32_t f = 1;
  const Thermo th = eos.thermo_from_eps(rho, eps, 0.1, T, &f);
  EXPECT_EQ(f, 0u);
  EXPECT_NEAR(th.press, 100 * rho * rho + 0.8 * rho * (eps - ec), 1e-18);
  EXPECT_NEAR(T, 0.8 * remnant::units::neutron_mass_MeV * (eps - ec), 1e-10);
  EXPECT_NEAR(eos.thermo(rho, T, 0.1).eps, eps, 1e-14);
  EXPECT_NEAR(th.cs2, numerical_cs2(eos, rho, eps), 1e-7);
  // Rule 8: eps below the cold curve is raised to it, T = 0.
  const Inversion low = eos.temperature(rho, 0.5 * ec, 0.1);
  EXPECT_EQ(low.flags, kInvBelowEpsLow);
  EXPECT_NEAR(low.eps, ec, 1e-15);
  EXPECT_EQ(low.T, 0.0);
}

TEST(EOSAnalytic, VariantHandleDispatchesOnce) {
  EosConfig cfg;
  cfg.type = "hybrid";
  cfg.poly_K = 100;
  cfg.poly_gammas = {2.0};
  cfg.gamma_th = 2.0;
  EOS eos = make_eos(cfg);
  EXPECT_FALSE(eos.is_tabulated());
  double sum = eos.visit([](const auto& e) {
    double s = 0;
    for (int i = 1; i <= 100; ++i) s += e.thermo(1e-5 * i, 1.0, 0.1).press;
    return s;
  });
  EXPECT_GT(sum, 0.0);
  EXPECT_NE(eos.describe().find("hybrid"), std::string::npos);
  cfg.type = "nonsense";
  EXPECT_THROW(make_eos(cfg), EosError);
}
