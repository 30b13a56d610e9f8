#pragma once
// Strong-stability-preserving Runge-Kutta methods in Shu-Osher form: each substep s sets
//   u <- a_s u0 + b_s (u + dt L(u)),
// and the right-hand side of substep s is evaluated at t0 + c_s dt.
#include <string>
#include <vector>

namespace remnant::mol {

struct RungeKuttaStage {
  double a;  // weight of the state at the beginning of the step
  double b;  // weight of the Euler-updated current state
  double c;  // time of the state the stage's RHS is evaluated on, in units of dt
};

// Throws std::invalid_argument for an unknown method.
const std::vector<RungeKuttaStage>& runge_kutta_stages(const std::string& method);

// The time (in units of dt) of the state after stage s.
double time_after_stage(const std::vector<RungeKuttaStage>& stages, std::size_t s);

// u <- a u0 + b (u + dt rhs) over n contiguous values.
inline void runge_kutta_update(double* u, const double* u0, const double* rhs, std::size_t n, double a, double b,
                               double dt) {
  for (std::size_t i = 0; i < n; ++i) u[i] = a * u0[i] + b * (u[i] + dt * rhs[i]);
}

// The same substep in increment form, u <- u0 + b ((u - u0) + dt L) (a + b = 1), for the magnetic
// face fields: a u0 + b u rounds a nearly static face value differently from u0 (1/3 x + 2/3 x != x
// for ~30 % of doubles), the same way every step, so the discrete div B of constrained transport
// grew linearly with the step count (2.7e-17 relative per step, 1.9e-12 after 86,000 steps of the
// spherical magnetised TOV star); with one rounding of a small increment it stays at round-off.
inline void runge_kutta_increment_update(double* u, const double* u0, const double* rhs, std::size_t n, double b,
                                         double dt) {
  for (std::size_t i = 0; i < n; ++i) u[i] = u0[i] + b * ((u[i] - u0[i]) + dt * rhs[i]);
}

}  // namespace remnant::mol
