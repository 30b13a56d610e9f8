// Neutrinoless beta equilibrium on the SFHo tables.
#include "EOS/beta_equilibrium.hpp"
#include "EOS/readers.hpp"
#include "eos_test_util.hpp"

using namespace remnant::eos;

namespace {
const double kRho = 8.5e13 * remnant::units::rho_cgs_to_code;
const double kT = 0.1;
}  // namespace

TEST(EOSBeta, YeAt8p5e13AndT0p1OnSfho) {
  const std::string sc = eos_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
  const std::string ch = eos_test::shared_eos("SFHo_reduced_39r_39t_20y_compose.h5");
  REQUIRE_TABLE(sc);
  REQUIRE_TABLE(ch);
  Tabulated<> eos_sc(load_table(sc));
  Tabulated<> eos_ch(load_table(ch));
  const BetaEquilibrium a = beta_equilibrium_ye(eos_sc, kRho, kT);
  const BetaEquilibrium b = beta_equilibrium_ye(eos_ch, kRho, kT);
  std::printf("[ beta-eq ] rho = 8.5e13 g/cm^3, T = 0.1 MeV:\n"
              "            SFHo StellarCollapse file (its mu_e column = CompOSE mu_l): Ye = %.6f\n"
              "            SFHo CompOSE HDF5 (mu_e = mu_l - mu_q, CompOSE manual):     Ye = %.6f\n",
              a.ye, b.ye);
  for (const auto& [eos, be] : {std::pair{&eos_sc, a}, std::pair{&eos_ch, b}}) {
    EXPECT_TRUE(be.bracketed);
    EXPECT_GT(be.ye, eos->bounds().ye_min);
    EXPECT_LT(be.ye, eos->bounds().ye_max);
    EXPECT_LT(std::abs(eos->mu_nu(kRho, kT, be.ye)), 1e-8);
  }
  EXPECT_NEAR(a.ye, 0.095, 0.01);  // SOURCES.md quotes about 0.095 for the StellarCollapse file
}

TEST(EOSBeta, ColdSliceIsMonotoneInPressure) {
  const std::string ch = eos_test::shared_eos("SFHo_reduced_39r_39t_20y_compose.h5");
  REQUIRE_TABLE(ch);
  Tabulated<> eos(load_table(ch));
  const BetaSlice s = cold_beta_slice(eos);
  ASSERT_EQ(s.rho.size(), 39u);
  EXPECT_EQ(s.T, eos.bounds().T_min);
  int bracketed = 0;
  for (std::size_t i = 0; i < s.rho.size(); ++i) {
    bracketed += s.bracketed[i];
    EXPECT_GE(s.ye[i], eos.bounds().ye_min);
    EXPECT_LE(s.ye[i], eos.bounds().ye_max);
  }
  EXPECT_GT(bracketed, 20);
  // Above nuclear saturation the cold pressure must rise with density.
  for (std::size_t i = 1; i < s.rho.size(); ++i)
    if (s.rho[i] > 3e14 * remnant::units::rho_cgs_to_code) {
      EXPECT_GT(s.press[i], s.press[i - 1]);
    }
}
