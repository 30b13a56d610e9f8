#pragma once
// <out_dir>/comm.tsv (Flesh::comm_stats): every rank's communication tallies (remnant/
// comm_counters.hpp), its scheduled functions' timers and its share of the grid, gathered to rank 0
// at the end of a run. Input of utils/scaling_model.
#include "remnant/context.hpp"
#include "remnant/scheduler.hpp"

namespace remnant {

// Collective over ctx.comm().
void write_comm_report(const Scheduler& s, Context& ctx);

}  // namespace remnant
