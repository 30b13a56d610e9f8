#pragma once
// The composite solver's levels ("tiers") built from a layout: the tier shapes, the patches with
// their shapes and lookup, parents and covered cells, interpolation windows, the runs of patches
// for line relaxation and the MPI split of the relaxation units.
#include <vector>

#include "XCFC/multigrid/composite_multigrid.hpp"
#include "composite_tier.hpp"

namespace remnant::xcfc {

// All tiers of a layout (tier 0: the base as one patch); throws std::invalid_argument for patches
// that are misaligned, repeated, outside the domain or not nested, or patch sizes that are odd or
// do not divide the base.
std::vector<Tier> build_tiers(const CompositeLayout& l, int nranks);

// The patch of tier T holding the in-domain cell I, or -1.
int locate(const Tier& T, const Cell& I);

}  // namespace remnant::xcfc
