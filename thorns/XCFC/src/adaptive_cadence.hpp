#pragma once
// The metric's prediction error and the adaptive cadence (XCFC::cadence_tolerance; README,
// "Cadence"). Every solve (and update) compares the metric just solved with what the cadence
// predicted for this time from the history (XCFC::extrapolation: hold, linear or quadratic): that
// difference is the error the matter saw at the end of the interval. With a tolerance, the interval
// to the next solve follows it like a step-size controller: the extrapolation error grows as the
// square of the interval, so the next interval is the last one times 0.8 sqrt(tolerance / error),
// at most doubled, within [XCFC::cadence_min, XCFC::solve_every].
#include <cstdint>

#include "remnant/context.hpp"

namespace remnant::xcfc {

// Largest differences between the metric now (Spacetime::metric, just solved or updated) and its
// prediction from XCFC::metric_history: |psi - psi_p|, |alpha - alpha_p| and the flat-metric norm
// |beta - beta_p| = sqrt(f_ij d beta^i d beta^j). `valid` is false before the first recorded
// metric (the initial solve). Call before record_history; a collective over the grid's ranks.
struct PredictionError {
  double psi = 0, alpha = 0, beta = 0;
  bool valid = false;
  double largest() const;  // the controller's error: the largest of the three
};
PredictionError prediction_error(Context& ctx);

// Matter steps from one solve to the next: XCFC::solve_every, or the adaptive interval when
// XCFC::cadence_tolerance > 0 (XCFC::cadence_min until the first evolution solve).
std::int64_t solve_interval(Context& ctx);

// After an evolution solve that closed an interval of `steps` matter steps with error `e`: the next
// interval (no-op without a tolerance).
void adapt_interval(Context& ctx, std::int64_t steps, const PredictionError& e);

// The controller itself, for tests: the interval after one of `steps` with error `error`.
std::int64_t next_interval(std::int64_t steps, double error, double tolerance, std::int64_t min_steps,
                           std::int64_t max_steps);

}  // namespace remnant::xcfc
