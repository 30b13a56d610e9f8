#pragma once
// CFL limit from the matter's characteristic speeds: max over cells and directions of |lambda| / dx.
#include "groups.hpp"

namespace remnant::grmhd {

double block_inverse_dt(const Groups& g, Block& b);

}  // namespace remnant::grmhd
