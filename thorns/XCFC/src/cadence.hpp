#pragma once
// When XCFC solves and what the metric is in between (paper, "Spacetime Solvers"; README,
// "Cadence"): a solve every XCFC::solve_every matter steps or when the psi residual exceeds
// XCFC::residual_trigger; between solves the metric is held or extrapolated linearly in time from
// the last two solves (XCFC::metric_history), and the warm starts of a solve are extrapolated alike.
#include <optional>

#include "XCFC/xcfc_system.hpp"
#include "grid_bridge.hpp"
#include "matter_coupling.hpp"
#include "remnant/context.hpp"

namespace remnant::xcfc {

// The weight w of last + w (last - before) at the current time, or none before two solves.
std::optional<double> extrapolation_weight(Context& ctx);

// The warm starts: the last solve's psi, alpha psi and potentials, or, once two solves are
// recorded, their linear extrapolation in time to now (w = (t - t_last) / (t_last - t_before)): the
// change between solves is then left to second order, which saves V-cycles.
void load_warm_start(Context& ctx, const GridBridge& br, const MatterGroups& g, int potentials, XcfcState& st);

// XCFC::potentials (the last solve's) -> XCFC::potentials_before, before the new ones are stored.
void shift_potentials(Context& ctx, int potentials);

// Shifts XCFC::metric_history (last -> before), stores the metric just solved as the last and
// counts the solve.
void record_history(Context& ctx);

// XCFC_Solve (prestep): a solve when the cadence or the residual trigger asks for one, else the
// metric extrapolated to the current time (XCFC::extrapolation = linear) with the primitives
// recovered with the new psi.
void evolution_step(Context& ctx);

}  // namespace remnant::xcfc
