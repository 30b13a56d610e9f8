#pragma once
// The metric inside a matter step (XCFC::stage_metric; README, "Cadence"). The metric is solved (or
// extrapolated between solves) once per step in `prestep`; with `hold` the Runge-Kutta stages all
// see that metric, so the matter-metric coupling is first order in dt (the head-on collision time
// moves linearly with the time step). With `extrapolate`, XCFC_StageMetric (scheduled in MoL_Step
// after MoL_Update, before MoL_PostStep) sets Spacetime::metric to its extrapolation from
// XCFC::metric_history (XCFC::extrapolation's order: linear from the last two metrics, quadratic
// from three) at the time of the state the stage just made, before the matter thorn recovers its
// primitives in MoL_PostStep: the next stage's right-hand side and the recovery of the densitised
// conserved variables then see the metric of their own time, with no extra recovery sweep. The
// step's last stage ends at the next step's time, so between solves the next prestep's
// extrapolation and its recovery are already done (cadence.cpp skips them).
#include "remnant/context.hpp"

namespace remnant::xcfc {

// XCFC::stage_metric == extrapolate.
bool stage_metric_on(Context& ctx);

// XCFC_StageMetric: the metric extrapolated to the current (stage) time; the hold before the
// history has two metrics.
void stage_metric(Context& ctx);

// At paramcheck: `extrapolate` needs an extrapolation order (XCFC::extrapolation != hold); throws
// InputError naming the parameters otherwise.
void check_stage_metric(Context& ctx);

}  // namespace remnant::xcfc
