#include "cadence.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

#include "adaptive_cadence.hpp"
#include "remnant/vars/Spacetime.hpp"
#include "remnant/vars/XCFC.hpp"
#include "runtime.hpp"
#include "solve_sequence.hpp"
#include "stage_metric.hpp"

namespace remnant::xcfc {

using Metric = vars::Spacetime::metric;
using History = vars::XCFC::metric_history;
using Potentials = vars::XCFC::potentials;
static_assert(History::idx::psi_before - History::idx::psi_last == Metric::ncomp &&
                  History::idx::psi_earlier - History::idx::psi_before == Metric::ncomp &&
                  History::idx::alpha_last - History::idx::psi_last == Metric::idx::alpha &&
                  History::idx::beta_last - History::idx::psi_last == Metric::idx::beta,
              "XCFC::metric_history holds three copies of Spacetime::metric's layout (thorn.yaml)");

std::array<double, 3> lagrange_weights(double t, const std::array<double, 3>& times) {
  std::array<double, 3> w{};
  for (int a = 0; a < 3; ++a) {
    double l = 1;
    for (int b = 0; b < 3; ++b)
      if (b != a) l *= (t - times[static_cast<std::size_t>(b)]) / (times[static_cast<std::size_t>(a)] - times[static_cast<std::size_t>(b)]);
    w[static_cast<std::size_t>(a)] = l;
  }
  return w;
}

std::optional<double> extrapolation_weight(Context& ctx) {
  const Runtime& rt = runtime(ctx);
  if (rt.history < 2 || !(rt.t_last > rt.t_before)) return std::nullopt;
  return (ctx.time() - rt.t_last) / (rt.t_last - rt.t_before);
}

std::optional<double> solve_extrapolation_weight(Context& ctx) {
  const Runtime& rt = runtime(ctx);
  if (rt.solve_history < 2 || !(rt.t_solve_last > rt.t_solve_before)) return std::nullopt;
  return (ctx.time() - rt.t_solve_last) / (rt.t_solve_last - rt.t_solve_before);
}

std::string resolved_extrapolation(Context& ctx) {
  const std::string kind = ctx.param<std::string>("XCFC", "extrapolation");
  if (kind != "auto") return kind;
  // Quadratic is the most accurate where it is stable (BU0-dyn F within 0.1 % at <= 15 steps per
  // solve); beyond, it amplifies the oscillation, so linear (README, Cadence).
  return ctx.param<std::int64_t>("XCFC", "solve_every") <= kQuadraticStableSolveEvery ? "quadratic" : "linear";
}

MetricExtrapolation metric_extrapolation(Context& ctx) {
  const Runtime& rt = runtime(ctx);
  MetricExtrapolation e;
  const std::string kind = resolved_extrapolation(ctx);
  const std::optional<double> weight = extrapolation_weight(ctx);
  if (kind == "hold" || !weight) return e;
  e.w = *weight;
  if (kind == "quadratic" && rt.history >= 3 && rt.t_before > rt.t_earlier) {
    e.kind = MetricExtrapolation::Kind::quadratic;
    e.l = lagrange_weights(ctx.time(), {rt.t_last, rt.t_before, rt.t_earlier});
  } else {
    e.kind = MetricExtrapolation::Kind::linear;
  }
  return e;
}

void load_warm_start(Context& ctx, const GridBridge& br, const SpacetimeGroups& g, int potentials, XcfcState& st,
                     bool with_X) {
  const std::optional<double> weight = extrapolation_weight(ctx), x_weight = solve_extrapolation_weight(ctx);
  const bool extrapolate = weight && *weight > 0, extrapolate_X = x_weight && *x_weight > 0;
  const double w = extrapolate ? *weight : 0.0, wx = extrapolate_X ? *x_weight : 0.0;
  const int hist = ctx.var("XCFC::metric_history"), before = ctx.var("XCFC::potentials_before");
  // last + w (last - before) of two fields of a block, per cell.
  auto extrapolated = [w](Field last, Field prev) {
    return [=](int i, int j, int k) { return last(i, j, k) + w * (last(i, j, k) - prev(i, j, k)); };
  };
  if (extrapolate) {
    st.psi = br.gather_cells([&](Block& b) { return extrapolated(b.field(hist, History::idx::psi_last), b.field(hist, History::idx::psi_before)); });
    st.alpha_psi = br.gather_cells([&](Block& b) {
      const auto psi = extrapolated(b.field(hist, History::idx::psi_last), b.field(hist, History::idx::psi_before)), alpha = extrapolated(b.field(hist, History::idx::alpha_last), b.field(hist, History::idx::alpha_before));
      return [=](int i, int j, int k) { return psi(i, j, k) * alpha(i, j, k); };
    });
  } else {
    st.psi = br.gather(g.metric, Metric::idx::psi);
    st.alpha_psi = br.gather_cells([&](Block& b) {
      const Field psi = b.field(g.metric, Metric::idx::psi), alpha = b.field(g.metric, Metric::idx::alpha);
      return [=](int i, int j, int k) { return psi(i, j, k) * alpha(i, j, k); };
    });
  }
  auto potential = [&](int c) {
    if (!extrapolate) return br.gather(potentials, c);
    return br.gather_cells([&](Block& b) { return extrapolated(b.field(potentials, c), b.field(before, c)); });
  };
  // X's potentials from the last two solves (updates between solves keep them).
  auto X_potential = [&](int c) {
    if (!extrapolate_X) return br.gather(potentials, c);
    return br.gather_cells([&](Block& b) {
      const Field last = b.field(potentials, c), prev = b.field(before, c);
      return [=](int i, int j, int k) { return last(i, j, k) + wx * (last(i, j, k) - prev(i, j, k)); };
    });
  };
  for (int a = 0; a < 3; ++a) {
    if (with_X) st.X_potentials.B[a] = X_potential(Potentials::idx::XB + a);
    st.beta_potentials.B[a] = potential(Potentials::idx::betaB + a);
  }
  if (with_X) st.X_potentials.chi = X_potential(Potentials::idx::Xchi);
  st.beta_potentials.chi = potential(Potentials::idx::betachi);
}

void shift_potentials(Context& ctx, int potentials, bool update) {
  const int before = ctx.var("XCFC::potentials_before");
  for (Block* b : ctx.grid().local_blocks())
    for (int c = update ? Potentials::idx::betaB : 0; c < Potentials::ncomp; ++c) {
      Field p = b->field(potentials, c), q = b->field(before, c);
      for_interior(*b, [&](int i, int j, int k) { q(i, j, k) = p(i, j, k); });
    }
}

void record_history(Context& ctx, bool update) {
  Runtime& rt = runtime(ctx);
  const int metric = ctx.var("Spacetime::metric"), hist = ctx.var("XCFC::metric_history");
  for (Block* b : ctx.grid().local_blocks())
    for (int c = 0; c < Metric::ncomp; ++c) {
      Field m = b->field(metric, c), last = b->field(hist, History::idx::psi_last + c), before = b->field(hist, History::idx::psi_before + c);
      Field earlier = b->field(hist, History::idx::psi_earlier + c);
      // The first solve fills every slot: the older ones are unused until more solves are recorded,
      // but they are declared written (and checkpointed), so they must hold defined values.
      const Field& previous = rt.history == 0 ? m : last;
      const Field& older = rt.history == 0 ? m : before;
      for_interior(*b, [&](int i, int j, int k) {
        earlier(i, j, k) = older(i, j, k);
        before(i, j, k) = previous(i, j, k);
        last(i, j, k) = m(i, j, k);
      });
    }
  rt.t_earlier = rt.t_before;
  rt.t_before = rt.t_last;
  rt.t_last = ctx.time();
  rt.history = std::min(rt.history + 1, 3);
  if (update) return;
  rt.t_solve_before = rt.t_solve_last;
  rt.t_solve_last = rt.t_last;
  rt.solve_history = std::min(rt.solve_history + 1, 2);
  ++rt.solves;
  rt.steps_since_solve = 0;
}

void cadence(Context& ctx) {
  Runtime& rt = runtime(ctx);
  rt.stage = Stage::idle;
  const std::int64_t every = ctx.param<std::int64_t>("XCFC", "solve_every");
  if (every <= 0) return;
  ++rt.steps_since_solve;
  if (rt.steps_since_solve >= solve_interval(ctx)) {
    rt.stage = Stage::solve, rt.reason = "cadence", rt.sources_due = true;
    return;
  }
  // XCFC::update_every: psi, alpha psi and beta^i re-solved with this step's matter (A^ij extrapolated).
  const std::int64_t update_every = ctx.param<std::int64_t>("XCFC", "update_every");
  if (update_every > 0 && rt.steps_since_solve % update_every == 0) {
    rt.stage = Stage::update, rt.sources_due = true;
    return;
  }
  rt.stage = resolved_extrapolation(ctx) != "hold" ? Stage::extrapolate : Stage::check_trigger;
  // XCFC::stage_metric = extrapolate: the step's last Runge-Kutta stage already extrapolated the
  // metric to this time from this history, and the matter was recovered with it (stage_metric.hpp;
  // blocks a regrid just made keep their prolonged metric until the next stage).
  if (rt.stage == Stage::extrapolate && stage_metric_on(ctx)) rt.stage = Stage::check_trigger;
  // The trigger's residual needs the sources of this step's matter.
  rt.sources_due = ctx.param<double>("XCFC", "residual_trigger") > 0;
}

// Between solves: the metric at the current time extrapolated linearly from the last two solves;
// the matter thorn then recovers the primitives with the new psi (the densitised conserved
// variables are the evolved ones). Holding the metric instead lags gravity by half a solve interval
// on average, which acts as a damping force on the stellar oscillations (README, "Cadence").
void extrapolate(Context& ctx) {
  Runtime& rt = runtime(ctx);
  if (rt.stage != Stage::extrapolate) return;
  rt.stage = Stage::check_trigger;
  if (write_extrapolated_metric(ctx, metric_extrapolation(ctx))) rt.recovery_due = true;
}

bool write_extrapolated_metric(Context& ctx, const MetricExtrapolation& e) {
  if (e.kind == MetricExtrapolation::Kind::hold) return false;
  const int metric = ctx.var("Spacetime::metric"), hist = ctx.var("XCFC::metric_history");
  const double w = e.w;
  const std::array<double, 3> l = e.l;
  for (Block* b : ctx.grid().local_blocks())
    for (int c = 0; c < Metric::ncomp; ++c) {
      Field m = b->field(metric, c);
      Field last = b->field(hist, History::idx::psi_last + c), before = b->field(hist, History::idx::psi_before + c);
      if (e.kind == MetricExtrapolation::Kind::quadratic) {
        Field earlier = b->field(hist, History::idx::psi_earlier + c);
        for_interior(*b, [&](int i, int j, int k) {
          m(i, j, k) = l[0] * last(i, j, k) + l[1] * before(i, j, k) + l[2] * earlier(i, j, k);
        });
      } else {
        for_interior(*b, [&](int i, int j, int k) { m(i, j, k) = last(i, j, k) + w * (last(i, j, k) - before(i, j, k)); });
      }
    }
  return true;
}

void residual_trigger(Context& ctx) {
  Runtime& rt = runtime(ctx);
  if (rt.stage != Stage::check_trigger) return;
  rt.stage = Stage::idle;
  const double trigger = ctx.param<double>("XCFC", "residual_trigger");
  if (trigger > 0 && psi_residual(ctx) > trigger) rt.stage = Stage::solve, rt.reason = "residual", rt.sources_due = true;
}

bool next_pass(Context& ctx) { return runtime(ctx).stage != Stage::idle; }

bool recovery_due(Context& ctx) {
  Runtime& rt = runtime(ctx);
  const bool due = rt.recovery_due;
  rt.recovery_due = false;
  return due;
}

// Runs the group once and clears the flag (a "run if" for the matter thorn's hook groups).
bool take(bool& flag) {
  const bool due = flag;
  flag = false;
  return due;
}

bool sources_due(Context& ctx) { return take(runtime(ctx).sources_due); }

bool initial_sources_due(Context& ctx) {
  Runtime& rt = runtime(ctx);
  if (rt.initial_sources_taken) return false;
  rt.initial_sources_taken = true;
  return ctx.param<std::string>("XCFC", "initial_metric") == "from_conserved";
}

bool psi_iteration_due(Context& ctx) {
  return ctx.param<std::string>("XCFC", "initial_metric") == "from_primitives" && !runtime(ctx).psi_iteration.done;
}

bool initial_pass(Context& ctx) {
  Runtime& rt = runtime(ctx);
  const bool first = !rt.initial_done;
  rt.initial_done = true;
  return first;
}

}  // namespace remnant::xcfc
