#pragma once
// Grid transfers between multigrid levels: volume-weighted restriction and linear prolongation,
// over cell ranges (the owned slabs of distributed levels).
#include <vector>

#include "level_ops.hpp"

namespace remnant::xcfc {

// Volume-weighted restriction of an interior array (fine -> coarse) over the fine cells RF, which
// cover the coarse cells RC (nested slabs): each coarse sum adds its fine cells in storage order.
void restrict_interior(const Level& F, const Level& C, const std::vector<double>& fine, std::vector<double>& coarse,
                       const Range& RF, const Range& RC);

// The same from and to ghosted arrays (coarse ghosts zeroed, to be filled by the caller).
void restrict_ghosted(const Level& F, const Level& C, const std::vector<double>& fine, std::vector<double>& coarse,
                      const Range& RF, const Range& RC);

// Adds (or, with `replace`, writes) the linear interpolation of a ghosted coarse array: each fine
// cell takes the coarse value plus a quarter of the central coarse slope per refined direction.
// Fine cells RF only; the coarse values they read are owned, halo or boundary ghosts.
void prolong(const Level& C, const Level& F, const std::vector<double>& coarse, std::vector<double>& fine, bool replace,
             const Range& RF);

}  // namespace remnant::xcfc
