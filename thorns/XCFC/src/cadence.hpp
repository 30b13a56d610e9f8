#pragma once
// When XCFC solves and what the metric is in between (paper, "Spacetime Solvers"; README,
// "Cadence"): a solve every XCFC::solve_every matter steps or when the psi residual exceeds
// XCFC::residual_trigger; between solves the metric is held or extrapolated linearly in time from
// the last two solves (XCFC::metric_history), and the warm starts of a solve are extrapolated alike;
// every XCFC::update_every steps between solves psi, alpha psi and beta^i are re-solved with the
// current matter (an update, recorded in the history like a solve; A^ij from the last two solves).
// The group XCFC_Solve (thorn.yaml) runs its steps in passes: XCFC_Extrapolate, the solve's steps
// (solve_sequence.hpp) with the recovery group, XCFC_ResidualTrigger; a step whose stage is not
// the current one does nothing.
#include <array>
#include <optional>
#include <string>

#include "XCFC/xcfc_system.hpp"
#include "grid_bridge.hpp"
#include "spacetime_groups.hpp"
#include "remnant/context.hpp"

namespace remnant::xcfc {

// Lagrange weights at time t of values at three distinct times (quadratic extrapolation).
std::array<double, 3> lagrange_weights(double t, const std::array<double, 3>& times);

// The weight w of last + w (last - before) at the current time, or none before two solves.
std::optional<double> extrapolation_weight(Context& ctx);

// What XCFC_Extrapolate makes of XCFC::metric_history at the current time: XCFC::extrapolation, or
// the hold (linear) while the history has fewer than two (three) metrics.
struct MetricExtrapolation {
  enum class Kind { hold, linear, quadratic } kind = Kind::hold;
  double w = 0;               // linear: last + w (last - before)
  std::array<double, 3> l{};  // quadratic: Lagrange weights of last, before, earlier
  double operator()(double last, double before, double earlier) const {
    switch (kind) {
      case Kind::linear: return last + w * (last - before);
      case Kind::quadratic: return l[0] * last + l[1] * before + l[2] * earlier;
      default: return last;
    }
  }
};
// Longest solve interval at which `auto` picks quadratic extrapolation (README, Cadence).
inline constexpr int kQuadraticStableSolveEvery = 15;

// XCFC::extrapolation with `auto` resolved by XCFC::solve_every.
std::string resolved_extrapolation(Context& ctx);

MetricExtrapolation metric_extrapolation(Context& ctx);

// The warm starts: the last solve's psi, alpha psi and potentials, or, once two solves are
// recorded, their linear extrapolation in time to now (w = (t - t_last) / (t_last - t_before)): the
// change between solves is then left to second order, which saves V-cycles. With updates between
// solves (XCFC::update_every) psi, alpha psi and beta's potentials come from the latest two metrics,
// solved or updated, and X's potentials from the last two solves (their own times).
// with_X = false (an update): X's potentials are left out (update_between_solves.hpp gives A^ij).
void load_warm_start(Context& ctx, const GridBridge& br, const SpacetimeGroups& g, int potentials, XcfcState& st,
                     bool with_X = true);

// The weight of X's potentials: (t - t_solve_last) / (t_solve_last - t_solve_before), or none
// before two solves.
std::optional<double> solve_extrapolation_weight(Context& ctx);

// XCFC::potentials (the last solve's) -> XCFC::potentials_before, before the new ones are stored;
// an update shifts only beta's (it keeps X's).
void shift_potentials(Context& ctx, int potentials, bool update = false);

// Shifts XCFC::metric_history (last -> before), stores the metric just solved as the last and
// counts the solve; an update between solves (XCFC::update_every) is recorded but not counted, so
// that the extrapolation and the warm starts take the latest two metrics, solved or updated.
void record_history(Context& ctx, bool update = false);

// XCFC_Cadence (prestep, before the group XCFC_Solve): what this step's passes of XCFC_Solve do:
// a solve when the cadence asks for one, an update of psi, alpha psi and beta^i every
// XCFC::update_every steps between solves, else the extrapolation (XCFC::extrapolation = linear or
// quadratic) or only the residual trigger's test.
void cadence(Context& ctx);
// XCFC_Extrapolate: the metric extrapolated to the current time; the recovery is then due.
void extrapolate(Context& ctx);
// Spacetime::metric's interior set to e applied to XCFC::metric_history; false (nothing written)
// for the hold.
bool write_extrapolated_metric(Context& ctx, const MetricExtrapolation& e);
// XCFC_ResidualTrigger: after the extrapolation (or hold), a solve in the next pass when the psi
// residual with the current matter exceeds XCFC::residual_trigger.
void residual_trigger(Context& ctx);

// Predicates of the groups: XCFC_Solve repeats while a stage is pending; XCFC_RecoverPrimitives
// runs once after psi changed; XCFC_Initial runs once.
bool next_pass(Context& ctx);
bool recovery_due(Context& ctx);
bool initial_pass(Context& ctx);
// XCFC_MatterSources runs before a solve (and before the residual trigger's test);
// XCFC_InitialMatterSources once for initial data given as conserved variables;
// XCFC_InitialPsiFromPrimitives repeats until the psi iteration of from_primitives is done.
bool sources_due(Context& ctx);
bool initial_sources_due(Context& ctx);
bool psi_iteration_due(Context& ctx);

}  // namespace remnant::xcfc
