// The adaptive cadence's controller (XCFC::cadence_tolerance): the next interval between solves
// from the last one and its prediction error, and the interval's survival through a checkpoint.
#include <gtest/gtest.h>

#include "adaptive_cadence.hpp"
#include "runtime.hpp"

namespace {

using remnant::xcfc::next_interval;

TEST(XCFCAdaptiveCadence, IntervalFollowsTheSquareRootOfToleranceOverError) {
  // error = tolerance / 4: 0.8 * 2 = 1.6 times longer; error = 4 tolerance: 0.4 times.
  EXPECT_EQ(next_interval(20, 0.25e-4, 1e-4, 1, 50), 32);
  EXPECT_EQ(next_interval(20, 4e-4, 1e-4, 1, 50), 8);
  // An error at the tolerance shortens by the safety factor.
  EXPECT_EQ(next_interval(10, 1e-4, 1e-4, 1, 50), 8);
}

TEST(XCFCAdaptiveCadence, GrowsAtMostTwofoldAndStaysWithinTheBounds) {
  EXPECT_EQ(next_interval(10, 1e-12, 1e-4, 1, 50), 20);  // tiny error: doubled, not 800x
  EXPECT_EQ(next_interval(10, 0.0, 1e-4, 1, 50), 20);    // nothing to predict yet: doubled
  EXPECT_EQ(next_interval(40, 1e-12, 1e-4, 1, 50), 50);  // at most solve_every
  EXPECT_EQ(next_interval(10, 1.0, 1e-4, 3, 50), 3);     // at least cadence_min
  EXPECT_EQ(next_interval(0, 0.0, 1e-4, 1, 50), 2);      // a solve in the same step counts as 1
}

TEST(XCFCAdaptiveCadence, IntervalAndUpdateErrorSurviveACheckpoint) {
  remnant::xcfc::Runtime saved;
  saved.interval = 37, saved.update_prediction = 0.1 + 0.2;
  remnant::xcfc::Runtime restored;
  remnant::xcfc::restore_persistent(restored, remnant::xcfc::save_persistent(saved));
  EXPECT_EQ(restored.interval, 37);
  EXPECT_EQ(restored.update_prediction, saved.update_prediction);  // exact: a hexadecimal float
  // A checkpoint written before the adaptive cadence: the interval starts afresh.
  remnant::xcfc::Runtime old;
  old.interval = 5, old.update_prediction = 1;
  remnant::xcfc::restore_persistent(old, "4 12 0x1.6p+2 0x1.5p+2 3 0x1.4p+2 2 7 0x1.6p+2 0x1.5p+2 2");
  EXPECT_EQ(old.interval, 0);
  EXPECT_EQ(old.update_prediction, 0);
}

}  // namespace
