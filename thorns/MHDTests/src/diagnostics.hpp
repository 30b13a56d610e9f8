#pragma once
// Per-cell diagnostics of the face fields for the TSV reductions of IO (any rank count, across
// regrids): the resolution-scaled relative divergence |div B| dx_min / max |B on the cell's faces|
// (the divB_max when reduced with `maximum`) and b2 = |B|^2 / 2 of the face means (its
// volume integral is the magnetic energy in flat space).
#include "remnant/context.hpp"
#include "remnant/grid.hpp"

namespace remnant::mhd_tests {

void cell_diagnostics(Block& b, const Field& bx, const Field& by, const Field& bz, const Field& div_rel, const Field& b2);

// Scheduled: fills MHDTests::divB and MHDTests::b2 on every local block.
void magnetic_diagnostics(Context& ctx);

}  // namespace remnant::mhd_tests
