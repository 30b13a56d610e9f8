#include "stage_metric.hpp"

#include <string>

#include "cadence.hpp"

namespace remnant::xcfc {

bool stage_metric_on(Context& ctx) { return ctx.param<std::string>("XCFC", "stage_metric") == "extrapolate"; }

void stage_metric(Context& ctx) {
  // The history holds the solves (and updates) up to this step's start; the stage times lie within
  // a step of it, or within the solve interval between solves, where XCFC_Extrapolate would
  // extrapolate to in prestep anyway.
  write_extrapolated_metric(ctx, metric_extrapolation(ctx));
}

void check_stage_metric(Context& ctx) {
  if (!stage_metric_on(ctx) || ctx.param<std::string>("XCFC", "extrapolation") != "hold") return;
  throw InputError(ctx.params().user_origin({{"XCFC", "stage_metric"}, {"XCFC", "extrapolation"}}),
                   "XCFC::stage_metric = extrapolate extrapolates the metric in time to each Runge-Kutta stage with "
                   "the order of XCFC::extrapolation, which is hold: set XCFC::extrapolation to auto, linear or "
                   "quadratic, or XCFC::stage_metric to hold");
}

}  // namespace remnant::xcfc
