// The superposition itself (no grid): the decay weights, the mirror symmetry z -> -z, the isolated
// star near each centre, flat space far away, the matter of each star and its infall velocity.
#include <gtest/gtest.h>

#include <cmath>

#include "HeadOn/binary.hpp"
#include "TOV/cold_slice.hpp"
#include "TOV/tov_solver.hpp"

using namespace remnant;

namespace {
struct Bu0 {
  std::unique_ptr<tov::ColdSlice> slice = tov::polytrope_slice(100.0, 2.0, 0.5);
  tov::TovStar star{*slice, 1.28e-3};
};
}  // namespace

TEST(HeadOnBinary, DecayWeights) {
  EXPECT_DOUBLE_EQ(headon::decay_weight(0.0, 60.0), 1.0);
  EXPECT_NEAR(headon::decay_weight(30.0, 60.0), std::exp(-1.0), 1e-15);
  EXPECT_NEAR(headon::decay_weight(60.0, 60.0), std::exp(-16.0), 1e-20);
}

TEST(HeadOnBinary, SuperpositionIsMirrorSymmetricAndIsolatedNearTheCentres) {
  const Bu0 s;
  const double d = 24, R = s.star.isotropic_radius();
  const headon::Binary bin(s.star, d, 0.05);
  for (double x : {0.0, 1.3, 5.0})
    for (double z : {0.3, 4.0, 12.0, 13.7, 30.0}) {
      const auto up = bin.at({x, 0.5 * x, z}), down = bin.at({x, 0.5 * x, -z});
      EXPECT_EQ(up.psi, down.psi);
      EXPECT_EQ(up.alpha, down.alpha);
      EXPECT_EQ(up.matter.rho, down.matter.rho);
      EXPECT_EQ(up.vz, -down.vz);
    }
  // At a centre: the isolated star plus kappa(d) (psi - 1) of the companion, kappa(d) = e^-16.
  const auto c = bin.at({0, 0, 0.5 * d});
  const auto iso = s.star.at(0.0), far = s.star.at(d);
  EXPECT_NEAR(c.psi, iso.psi + std::exp(-16.0) * (far.psi - 1), 1e-14);
  EXPECT_EQ(c.star, 1);
  EXPECT_EQ(c.matter.rho, iso.rho);
  EXPECT_EQ(c.vz, -0.05);  // towards the other star
  EXPECT_EQ(bin.at({0, 0, -0.5 * d}).vz, 0.05);
  // Between the stars and outside them: no matter; far away: flat (the weights cut the 1/r tails,
  // which is why the metric must be solved again).
  EXPECT_EQ(bin.at({0, 0, 0}).star, -1);
  EXPECT_EQ(bin.at({0, 0, 0.5 * d + 1.01 * R}).matter.rho, 0.0);
  EXPECT_NEAR(bin.at({0, 0, 3 * d}).psi, 1.0, 1e-12);
  EXPECT_GT(bin.at({0, 0, 0}).psi, 1.0);
}
