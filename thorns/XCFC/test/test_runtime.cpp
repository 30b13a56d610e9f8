// XCFC's per-simulation state is a service of each Context (not a function-static object shared by
// every simulation in the process), and its persistent counters survive a checkpoint bit for bit.
#include <gtest/gtest.h>

#include "remnant/context.hpp"
#include "remnant/error.hpp"
#include "cadence.hpp"
#include "runtime.hpp"

namespace {

using namespace remnant;

TEST(XCFCRuntime, EachSimulationHasItsOwnState) {
  const Parameters params;
  const VariableRegistry vars;
  Context a(params, vars, MPI_COMM_SELF), b(params, vars, MPI_COMM_SELF);
  xcfc::Runtime& ra = xcfc::runtime(a);
  ra.solves = 7;
  ra.steps_since_solve = 3;
  EXPECT_EQ(&xcfc::runtime(a), &ra);
  EXPECT_TRUE(a.has_service("XCFC::runtime"));
  EXPECT_EQ(xcfc::runtime(b).solves, 0);
  EXPECT_EQ(xcfc::runtime(b).steps_since_solve, 0);
}

TEST(XCFCRuntime, PersistentCountersRoundTripBitForBit) {
  xcfc::Runtime saved;
  saved.steps_since_solve = 4, saved.solves = 12, saved.history = 2;
  saved.t_last = 0.1 + 0.2, saved.t_before = 1.0 / 3.0, saved.t_earlier = -2.0 / 7.0;
  xcfc::Runtime restored;
  xcfc::restore_persistent(restored, xcfc::save_persistent(saved));
  EXPECT_EQ(restored.steps_since_solve, 4);
  EXPECT_EQ(restored.solves, 12);
  EXPECT_EQ(restored.history, 2);
  EXPECT_EQ(restored.t_last, saved.t_last);  // exact: hexadecimal floats
  EXPECT_EQ(restored.t_before, saved.t_before);
  EXPECT_EQ(restored.t_earlier, saved.t_earlier);
  EXPECT_THROW(xcfc::restore_persistent(restored, "4 12"), RunError);
}

TEST(XCFCRuntime, UpdateCountersAndSolveTimesRoundTrip) {
  // XCFC::update_every: the updates since the last solve and the times of the last two solves
  // (X's extrapolation) survive a checkpoint.
  xcfc::Runtime saved;
  saved.history = 3, saved.t_last = 5.5, saved.t_before = 5.25, saved.t_earlier = 5.0;
  saved.updates = 9, saved.update_cycles = 31, saved.solve_history = 2;
  saved.t_solve_last = 1.0 / 3.0 + 4, saved.t_solve_before = 0.1 + 0.7;
  xcfc::Runtime restored;
  xcfc::restore_persistent(restored, xcfc::save_persistent(saved));
  EXPECT_EQ(restored.updates, 9);
  EXPECT_EQ(restored.update_cycles, 31);
  EXPECT_EQ(restored.solve_history, 2);
  EXPECT_EQ(restored.t_solve_last, saved.t_solve_last);
  EXPECT_EQ(restored.t_solve_before, saved.t_solve_before);
  // A checkpoint written before the updates existed: no updates, the last solves are the history's.
  xcfc::Runtime old;
  xcfc::restore_persistent(old, "4 12 0x1.6p+2 0x1.5p+2 3 0x1.4p+2");
  EXPECT_EQ(old.updates, 0);
  EXPECT_EQ(old.update_cycles, 0);
  EXPECT_EQ(old.t_solve_last, 5.5);
  EXPECT_EQ(old.t_solve_before, 5.25);
  EXPECT_EQ(old.solve_history, 2);
}

TEST(XCFCCadence, QuadraticExtrapolationWeightsAreExactForQuadratics) {
  // Unequal solve intervals (a residual-triggered solve) and a time past the last solve.
  const std::array<double, 3> times{2.5, 1.75, 0.5};
  const double t = 3.1;
  const std::array<double, 3> w = xcfc::lagrange_weights(t, times);
  auto f = [](double x) { return 0.3 - 1.7 * x + 0.45 * x * x; };
  EXPECT_NEAR(w[0] * f(times[0]) + w[1] * f(times[1]) + w[2] * f(times[2]), f(t), 1e-13);
  EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-15);
  // At a solve time the extrapolation is that solve's metric.
  const std::array<double, 3> at_last = xcfc::lagrange_weights(times[0], times);
  EXPECT_EQ(at_last[0], 1.0);
  EXPECT_EQ(at_last[1], 0.0);
}

}  // namespace
