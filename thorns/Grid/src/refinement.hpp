#pragma once
// Deciding the next mesh: per-block wishes (refine, keep, coarsen) from the criteria and the
// static regions, limited to [0, max_level], then 2:1 balance across faces, edges and corners
// (through periodic, mirror, axis and origin faces too). Runs identically on every rank.
#include <span>
#include <string>
#include <vector>

#include "boundary_map.hpp"
#include "forest.hpp"

namespace remnant::grid {

struct LevelBounds {
  int min_level = 0;
  int max_level = 0;
};

// The levels the static regions allow for a block (at_most wins over at_least).
LevelBounds region_bounds(const GridConfig& config, const BlockKey& key);

// The leaves after one regrid step: a leaf whose wish (+1, 0, -1 per gid) asks for more
// refinement than it has is split (and so are the coarser neighbours balance requires); a
// complete family of leaves that all wish to coarsen, whose parent the regions allow and whose
// parent would stay balanced, is merged. At most one level up or down per call.
std::vector<BlockKey> next_leaves(const GridConfig& config, const Forest& forest, const BoundaryMaps& maps,
                                  std::span<const int> wishes);

// Empty when every leaf's face, edge and corner neighbours are at most one level apart;
// otherwise a description of the first violation.
std::string balance_violation(const GridConfig& config, const Forest& forest, const BoundaryMaps& maps);

// The static layout: level 0 refined (repeatedly) until every region is satisfied.
std::vector<BlockKey> initial_leaves(const GridConfig& config, const BoundaryMaps& maps);

}  // namespace remnant::grid
