// The target grid seen from the 3D data: which points it holds, with what fraction of their cell,
// and its mirror images (what the rest-mass bookkeeping of the hand-off rests on).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "HandOff/target_domain.hpp"

namespace {

using namespace remnant;
using remnant::handoff::TargetDomain;
constexpr double pi = std::numbers::pi;

TargetDomain cylinder_2d() {  // R in [0, 10], z in [0, 8], mirror at z = 0
  TargetDomain t;
  t.coordinates = CoordinateSystem::cylindrical;
  t.dimension = 2;
  t.lo = {0, 0, 0}, t.hi = {10, 8, 2 * pi};
  t.mirror = {false, false, true};
  return t;
}

TEST(TargetDomain, CylinderHalvesPointsOnItsMirrorPlane) {
  const TargetDomain t = cylinder_2d();
  EXPECT_TRUE(t.averages_over_phi());
  EXPECT_DOUBLE_EQ(t.fraction_inside({3, -4, 0.0}, 0.5), 0.5);   // on z = 0: half its cell
  EXPECT_DOUBLE_EQ(t.fraction_inside({3, -4, 0.1}, 0.5), 0.7);   // [-0.15, 0.35]: 0.35 / 0.5
  EXPECT_DOUBLE_EQ(t.fraction_inside({3, -4, 2.0}, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(t.fraction_inside({3, -4, -1.0}, 0.5), 0.0);  // the mirror side
  EXPECT_DOUBLE_EQ(t.fraction_inside({8, 8, 1.0}, 0.5), 0.0);    // R = 11.3 > 10
  EXPECT_DOUBLE_EQ(t.fraction_inside({3, 4, 8.0}, 0.5), 0.5);    // on the upper face z = 8
  // The covered region: the grid unfolded by its mirror.
  EXPECT_TRUE(t.contains(t.fold({3, -4, -5})));
  EXPECT_FALSE(t.contains(t.fold({3, -4, -9})));
  const Point3 x = t.coordinates_of({0, -2, 1});
  EXPECT_NEAR(x[0], 2, 1e-15);
  EXPECT_NEAR(x[1], 1, 1e-15);
  EXPECT_NEAR(x[2], 1.5 * pi, 1e-15);
}

TEST(TargetDomain, SphericalEquatorIsThePlaneZ0) {
  TargetDomain t;
  t.coordinates = CoordinateSystem::spherical;
  t.dimension = 2;
  t.lo = {0, 0, 0}, t.hi = {10, pi / 2, 2 * pi};
  t.mirror = {false, false, true};
  EXPECT_DOUBLE_EQ(t.fraction_inside({3, 0, 0.0}, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(t.fraction_inside({3, 0, 0.1}, 0.5), 0.7);
  EXPECT_DOUBLE_EQ(t.fraction_inside({3, 0, -0.3}, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(t.fraction_inside({0, 0, 9.9}, 0.5), 1.0);   // on the axis, inside r = 10
  EXPECT_DOUBLE_EQ(t.fraction_inside({8, 0, 7}, 0.5), 0.0);     // r = 10.6
}

TEST(TargetDomain, CartesianOctantFractionsMultiply) {
  TargetDomain t;
  t.lo = {0, 0, 0}, t.hi = {12, 12, 12};
  t.mirror = {true, true, true};
  EXPECT_FALSE(t.averages_over_phi());
  EXPECT_DOUBLE_EQ(t.fraction_inside({0, 0, 0}, 1.0), 0.125);   // the corner point: an eighth
  EXPECT_DOUBLE_EQ(t.fraction_inside({0, 5, 5}, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(t.fraction_inside({12, 12, 5}, 1.0), 0.25);
  const Point3 f = t.fold({-1, -2, 3});
  EXPECT_EQ(f[0], 1);
  EXPECT_EQ(f[1], 2);
  EXPECT_EQ(f[2], 3);
}

}  // namespace
