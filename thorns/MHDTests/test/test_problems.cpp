// The problem tables against the published values (Balsara 2001 section 5 / Giacomazzo & Rezzolla
// 2006 Table 1; Komissarov 1999 section 7; Del Zanna et al. 2003 section 4; Beckwith & Stone 2011).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "problems.hpp"

using namespace remnant::mhd_tests;

namespace {
void expect_state(const FluidState& s, double rho, double p, std::array<double, 3> v, std::array<double, 3> B) {
  EXPECT_DOUBLE_EQ(s.rho, rho);
  EXPECT_DOUBLE_EQ(s.press, p);
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(s.v[c], v[c]) << "v component " << c;
    EXPECT_DOUBLE_EQ(s.B[c], B[c]) << "B component " << c;
  }
}
}  // namespace

TEST(MHDTestsProblems, BalsaraStatesAsPublished) {
  auto p = riemann_problem(Problem::balsara1);
  expect_state(p.left, 1, 1, {0, 0, 0}, {0.5, 1, 0});
  expect_state(p.right, 0.125, 0.1, {0, 0, 0}, {0.5, -1, 0});
  p = riemann_problem(Problem::balsara2);
  expect_state(p.left, 1, 30, {0, 0, 0}, {5, 6, 6});
  expect_state(p.right, 1, 1, {0, 0, 0}, {5, 0.7, 0.7});
  p = riemann_problem(Problem::balsara3);
  expect_state(p.left, 1, 1000, {0, 0, 0}, {10, 7, 7});
  expect_state(p.right, 1, 0.1, {0, 0, 0}, {10, 0.7, 0.7});
  p = riemann_problem(Problem::balsara4);
  expect_state(p.left, 1, 0.1, {0.999, 0, 0}, {10, 7, 7});
  expect_state(p.right, 1, 0.1, {-0.999, 0, 0}, {10, -7, -7});
  p = riemann_problem(Problem::balsara5);
  expect_state(p.left, 1.08, 0.95, {0.4, 0.3, 0.2}, {2, 0.3, 0.3});
  expect_state(p.right, 1, 1, {-0.45, -0.2, 0.2}, {2, -0.7, 0.5});
  for (Problem q : {Problem::balsara1, Problem::balsara2, Problem::balsara3, Problem::balsara4, Problem::balsara5}) {
    const auto r = riemann_problem(q);
    EXPECT_EQ(r.left.B[0], r.right.B[0]) << "the normal field must be continuous (" << name_of(q) << ")";
    const double v2 = r.left.v[0] * r.left.v[0] + r.left.v[1] * r.left.v[1] + r.left.v[2] * r.left.v[2];
    EXPECT_LT(v2, 1.0);
  }
}

TEST(MHDTestsProblems, AdiabaticIndicesDomainsAndFinalTimes) {
  EXPECT_DOUBLE_EQ(setup_of(Problem::balsara1).gamma, 2.0);
  for (Problem q : {Problem::balsara2, Problem::balsara3, Problem::balsara4, Problem::balsara5, Problem::field_loop,
                    Problem::rotor})
    EXPECT_DOUBLE_EQ(setup_of(q).gamma, 5.0 / 3.0) << name_of(q);
  EXPECT_DOUBLE_EQ(setup_of(Problem::cylindrical_blast).gamma, 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(setup_of(Problem::balsara1).t_final, 0.4);
  EXPECT_DOUBLE_EQ(setup_of(Problem::balsara4).t_final, 0.4);
  EXPECT_DOUBLE_EQ(setup_of(Problem::balsara5).t_final, 0.55);
  EXPECT_DOUBLE_EQ(setup_of(Problem::cylindrical_blast).t_final, 4.0);
  EXPECT_DOUBLE_EQ(setup_of(Problem::cylindrical_blast).xmax[0], 6.0);
  EXPECT_DOUBLE_EQ(setup_of(Problem::rotor).t_final, 0.4);
  // The field loop crosses its periodic box [-1,1]x[-0.5,0.5] exactly once by t_final.
  const ProblemSetup fl = setup_of(Problem::field_loop);
  const FieldLoopParams loop;
  for (int d = 0; d < 2; ++d)
    EXPECT_NEAR(loop.velocity[d] * fl.t_final, fl.xmax[d] - fl.xmin[d], 1e-14) << "direction " << d;
}

TEST(MHDTestsProblems, NamesRoundTripAndUnknownNamesAreRefused) {
  for (int i = 0; i <= static_cast<int>(Problem::rotor); ++i) {
    const auto p = static_cast<Problem>(i);
    EXPECT_EQ(problem_from_name(name_of(p)), p);
  }
  EXPECT_THROW(problem_from_name("balsara6"), std::invalid_argument);
  EXPECT_THROW(riemann_problem(Problem::rotor), std::invalid_argument);
}

TEST(MHDTestsProblems, KomissarovBlastProfile) {
  const BlastParams p;
  expect_state(blast_state(p, 0.1, -0.3), 1e-2, 1, {0, 0, 0}, {1, 0, 0});
  expect_state(blast_state(p, 3, 4), 1e-4, 3e-5, {0, 0, 0}, {1, 0, 0});
  // Log-linear transition: the geometric mean half way.
  const FluidState mid = blast_state(p, 0, 0.9);
  EXPECT_NEAR(mid.rho, 1e-3, 1e-15);
  EXPECT_NEAR(mid.press, std::sqrt(3e-5), 1e-15);
}

TEST(MHDTestsProblems, RotorSpinsRigidlyInsideAndRestsOutside) {
  const RotorParams p;
  const FluidState in = rotor_state(p, 0.05, 0.08);  // r = 0.094: inside
  EXPECT_DOUBLE_EQ(in.rho, 10);
  EXPECT_NEAR(in.v[0], -9.95 * 0.08, 1e-15);
  EXPECT_NEAR(in.v[1], 9.95 * 0.05, 1e-15);
  EXPECT_LT(std::hypot(in.v[0], in.v[1]), 0.995 + 1e-12);
  expect_state(rotor_state(p, 0.2, 0.0), 1, 1, {0, 0, 0}, {1, 0, 0});
}

TEST(MHDTestsProblems, FieldLoopPotentialAndEnergy) {
  FieldLoopParams p;
  EXPECT_DOUBLE_EQ(field_loop_potential(p, 0, 0), 1e-3 * 0.3);
  EXPECT_DOUBLE_EQ(field_loop_potential(p, 0.3, 0.0), 0.0);
  // Periodic images: the loop centred at the right edge is seen from the left edge.
  p.centre = {0.95, 0};
  EXPECT_NEAR(field_loop_potential(p, -0.95, 0), 1e-3 * (0.3 - 0.1), 1e-15);
  // Energies by midpoint quadrature of |grad A|^2 / 2 on a fine grid.
  for (auto profile : {FieldLoopParams::Profile::beckwith_stone, FieldLoopParams::Profile::smooth}) {
    FieldLoopParams q;
    q.profile = profile;
    const int n = 1200;
    const double h = 0.8 / n;
    double e = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = -0.4 + (i + 0.5) * h, y = -0.4 + (j + 0.5) * h;
        const double ax = (field_loop_potential(q, x + 1e-6, y) - field_loop_potential(q, x - 1e-6, y)) / 2e-6;
        const double ay = (field_loop_potential(q, x, y + 1e-6) - field_loop_potential(q, x, y - 1e-6)) / 2e-6;
        e += 0.5 * (ax * ax + ay * ay) * h * h;
      }
    EXPECT_NEAR(e / field_loop_magnetic_energy(q), 1.0, 2e-3);
  }
}
