#pragma once
// <out_dir>/handoff_profiles.tsv: the 3D data and the grid after the metric solve, cell by cell along
// two lines of the grid: line 0 along direction 0 through the first cells of the other directions
// (the equator of a cylindrical grid with a mirror at z = 0), line 1 along direction 1 through the
// first cells of directions 0 and 2 (the axis of a cylindrical grid). utils/plot_handoff draws it.
#include <string>

#include "remnant/context.hpp"

namespace remnant::handoff {

// Collective; rank 0 writes. Returns the number of rows.
int write_profiles(Context& ctx, const std::string& path);

}  // namespace remnant::handoff
