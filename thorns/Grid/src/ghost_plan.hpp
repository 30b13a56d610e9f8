#pragma once
// Which transfers fill the ghost zones of a block: for each of the 3^d - 1 ghost boxes, its image
// in the domain (through the boundary maps) and the leaves that cover that image (same level,
// one coarser, or the finer children), with the source boxes they must provide.
#include <array>
#include <vector>

#include "boundary_map.hpp"
#include "forest.hpp"
#include "transfer.hpp"

namespace remnant::grid {

// Appends, in a fixed order, the transfers that fill the ghosts of block `gid` for a centering
// with staggering `stagger`. Ghost boxes beyond outflow faces are left to the outflow pass.
void plan_ghost_transfers(const Forest& forest, const BoundaryMaps& maps, std::int64_t gid,
                          const std::array<int, 3>& stagger, int ghost_zones, std::vector<Transfer>& out);

// The interior points (stagger included) of a block of `forest` as a global box on its level.
GlobalBox interior_box(const Forest& forest, const BlockKey& key, const std::array<int, 3>& stagger);

}  // namespace remnant::grid
