#pragma once
// Test fixture shared by the field's convergence tests (HandOffMagnetic, HandOffCurvilinearField):
// the magnetised TOV star as 3D Carpet data at two resolutions, written once per test suite:
// coarse (spacing 0.5 over the star, two levels) and fine (a third level of spacing 0.25).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "magnetised_tov.hpp"

namespace remnant::handoff::testing {

class MagnetisedTovPair : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    coarse_ = new MagnetisedTov(kAt, false);
    fine_ = new MagnetisedTov(kAt, true);
  }
  static void TearDownTestSuite() {
    delete coarse_;
    delete fine_;
    coarse_ = fine_ = nullptr;
  }
  static inline MagnetisedTov* coarse_ = nullptr;
  static inline MagnetisedTov* fine_ = nullptr;
};

// E_mag's error against the exact energy from the coarse to the fine hand-off: smaller, of order > 1.
inline void expect_convergence(const char* name, double coarse, double fine) {
  const double order = std::log2(std::abs(coarse) / std::abs(fine));
  std::printf("%s: E_mag imported vs exact %+.2e -> %+.2e (order %.2f)\n", name, coarse, fine, order);
  EXPECT_LT(std::abs(fine), std::abs(coarse));
  EXPECT_GT(order, 1.0);
}

}  // namespace remnant::handoff::testing
