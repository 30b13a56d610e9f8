#pragma once
// The record of the solves: one row of <out_dir>/xcfc.tsv per solve (cycles and relative residuals
// of each equation, wall time) and a warning for a solve that ran out of cycles.
#include <cstdint>

#include "XCFC/xcfc_system.hpp"
#include "remnant/context.hpp"

namespace remnant::xcfc {

// `interval`: matter steps since the previous solve; the prediction errors come from the runtime.
void write_tsv(Context& ctx, const char* reason, const XcfcStats& s, std::int64_t interval, double seconds);
void warn_unconverged(Context& ctx, const XcfcStats& s);

}  // namespace remnant::xcfc
