// XCFC's per-simulation state is a service of each Context (not a function-static object shared by
// every simulation in the process), and its persistent counters survive a checkpoint bit for bit.
#include <gtest/gtest.h>

#include "remnant/context.hpp"
#include "remnant/error.hpp"
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
  saved.t_last = 0.1 + 0.2, saved.t_before = 1.0 / 3.0;
  xcfc::Runtime restored;
  xcfc::restore_persistent(restored, xcfc::save_persistent(saved));
  EXPECT_EQ(restored.steps_since_solve, 4);
  EXPECT_EQ(restored.solves, 12);
  EXPECT_EQ(restored.history, 2);
  EXPECT_EQ(restored.t_last, saved.t_last);  // exact: hexadecimal floats
  EXPECT_EQ(restored.t_before, saved.t_before);
  EXPECT_THROW(xcfc::restore_persistent(restored, "4 12"), RunError);
}

}  // namespace
