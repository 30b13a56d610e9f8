#include "adaptive_cadence.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cadence.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/vars/Spacetime.hpp"
#include "remnant/vars/XCFC.hpp"
#include "runtime.hpp"

namespace remnant::xcfc {

using Metric = vars::Spacetime::metric;
using History = vars::XCFC::metric_history;

double PredictionError::largest() const { return std::max({psi, alpha, beta}); }

PredictionError prediction_error(Context& ctx) {
  PredictionError e;
  if (runtime(ctx).history == 0) return e;
  const MetricExtrapolation predict = metric_extrapolation(ctx);
  const int metric = ctx.var("Spacetime::metric"), hist = ctx.var("XCFC::metric_history");
  // The prediction of component c at one cell.
  auto predicted = [&](Block& b, int c) {
    const Field last = b.field(hist, History::idx::psi_last + c), before = b.field(hist, History::idx::psi_before + c);
    const Field earlier = b.field(hist, History::idx::psi_earlier + c);
    return [=](int i, int j, int k) { return predict(last(i, j, k), before(i, j, k), earlier(i, j, k)); };
  };
  double local[3] = {0, 0, 0};
  for (Block* b : ctx.grid().local_blocks()) {
    const auto psi_p = predicted(*b, Metric::idx::psi), alpha_p = predicted(*b, Metric::idx::alpha);
    const Field psi = b->field(metric, Metric::idx::psi), alpha = b->field(metric, Metric::idx::alpha);
    const auto beta_p0 = predicted(*b, Metric::idx::beta), beta_p1 = predicted(*b, Metric::idx::beta + 1),
               beta_p2 = predicted(*b, Metric::idx::beta + 2);
    const Field beta0 = b->field(metric, Metric::idx::beta), beta1 = b->field(metric, Metric::idx::beta + 1),
                beta2 = b->field(metric, Metric::idx::beta + 2);
    const CoordinateSystem coords = b->coordinates;
    std::vector<double> sin_theta(static_cast<std::size_t>(b->n[1]));  // once per row, not per cell
    for (int j = 0; j < b->n[1]; ++j) sin_theta[static_cast<std::size_t>(j)] = std::sin(b->x(1, j));
    for_interior(*b, [&](int i, int j, int k) {
      local[0] = std::max(local[0], std::abs(psi(i, j, k) - psi_p(i, j, k)));
      local[1] = std::max(local[1], std::abs(alpha(i, j, k) - alpha_p(i, j, k)));
      const Point3 f = coords::metric_diagonal(coords, {b->x(0, i), b->x(1, j), b->x(2, k)}, sin_theta[static_cast<std::size_t>(j)]);
      const double d0 = beta0(i, j, k) - beta_p0(i, j, k), d1 = beta1(i, j, k) - beta_p1(i, j, k),
                   d2 = beta2(i, j, k) - beta_p2(i, j, k);
      local[2] = std::max(local[2], std::sqrt(f[0] * d0 * d0 + f[1] * d1 * d1 + f[2] * d2 * d2));
    });
  }
  double global[3];
  MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_MAX, ctx.grid().comm());
  e.psi = global[0], e.alpha = global[1], e.beta = global[2], e.valid = true;
  return e;
}

std::int64_t next_interval(std::int64_t steps, double error, double tolerance, std::int64_t min_steps,
                           std::int64_t max_steps) {
  // Linear extrapolation: error ~ interval^2; 0.8 keeps the next error below the tolerance when the
  // metric's second derivative grows, doubling at most keeps a quiet spell from jumping far ahead.
  const double factor = error > 0 ? std::min(2.0, 0.8 * std::sqrt(tolerance / error)) : 2.0;
  const auto next = static_cast<std::int64_t>(std::floor(static_cast<double>(std::max<std::int64_t>(steps, 1)) * factor));
  return std::clamp(next, min_steps, std::max(min_steps, max_steps));
}

std::int64_t solve_interval(Context& ctx) {
  const std::int64_t every = ctx.param<std::int64_t>("XCFC", "solve_every");
  if (!(ctx.param<double>("XCFC", "cadence_tolerance") > 0)) return every;
  const Runtime& rt = runtime(ctx);
  const std::int64_t min_steps = std::min(every, ctx.param<std::int64_t>("XCFC", "cadence_min"));
  return rt.interval > 0 ? std::clamp(rt.interval, min_steps, every) : min_steps;
}

void adapt_interval(Context& ctx, std::int64_t steps, const PredictionError& e) {
  const double tolerance = ctx.param<double>("XCFC", "cadence_tolerance");
  if (!(tolerance > 0) || !e.valid) return;
  const std::int64_t every = ctx.param<std::int64_t>("XCFC", "solve_every");
  runtime(ctx).interval =
      next_interval(steps, e.largest(), tolerance, std::min(every, ctx.param<std::int64_t>("XCFC", "cadence_min")), every);
}

}  // namespace remnant::xcfc
