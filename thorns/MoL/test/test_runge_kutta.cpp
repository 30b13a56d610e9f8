#include <gtest/gtest.h>

#include <cmath>

#include "runge_kutta.hpp"

using namespace remnant::mol;

namespace {
// Integrates du/dt = lambda u from 0 to 1 and returns the error against exp(lambda).
double error_for(const std::string& method, int steps, double lambda) {
  const auto& stages = runge_kutta_stages(method);
  const double dt = 1.0 / steps;
  double u = 1.0;
  for (int n = 0; n < steps; ++n) {
    const double u0 = u;
    for (const auto& s : stages) {
      const double rhs = lambda * u;
      runge_kutta_update(&u, &u0, &rhs, 1, s.a, s.b, dt);
    }
  }
  return std::abs(u - std::exp(lambda));
}
// Integrates du/dt = t^2 to check the substep times c_s: exact for rk3.
double time_dependent(const std::string& method) {
  const auto& stages = runge_kutta_stages(method);
  const double dt = 0.5;
  double u = 0, t = 0;
  for (int n = 0; n < 2; ++n) {
    const double u0 = u;
    for (const auto& s : stages) {
      const double ts = t + s.c * dt;
      const double rhs = ts * ts;
      runge_kutta_update(&u, &u0, &rhs, 1, s.a, s.b, dt);
    }
    t += dt;
  }
  return u;
}
}  // namespace

TEST(RungeKutta, ConvergenceOrders) {
  for (auto [method, order] : {std::pair{"rk3", 3.0}, {"rk2", 2.0}, {"euler", 1.0}}) {
    const double e1 = error_for(method, 40, -1.3), e2 = error_for(method, 80, -1.3);
    EXPECT_NEAR(std::log2(e1 / e2), order, 0.1) << method;
  }
}

TEST(RungeKutta, SubstepTimes) {
  EXPECT_NEAR(time_dependent("rk3"), 1.0 / 3.0, 1e-15);
  const auto& rk3 = runge_kutta_stages("rk3");
  EXPECT_DOUBLE_EQ(time_after_stage(rk3, 0), 1.0);
  EXPECT_DOUBLE_EQ(time_after_stage(rk3, 1), 0.5);
  EXPECT_DOUBLE_EQ(time_after_stage(rk3, 2), 1.0);
  EXPECT_THROW(runge_kutta_stages("rk4"), std::invalid_argument);
}
