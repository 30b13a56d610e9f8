#pragma once
// CFL limit from the matter's characteristic speeds: max over cells and directions of |lambda| / dx.
#include "groups.hpp"

namespace remnant::grmhd {

double block_inverse_dt(const Groups& g, Block& b);
// The same with the fast-magnetosonic speed of the cell-centred field B^i (group bvec).
double block_inverse_dt_mhd(const Groups& g, int bvec, Block& b);

}  // namespace remnant::grmhd
