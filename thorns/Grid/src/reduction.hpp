#pragma once
// Global reductions that give the same bits for any number of ranks: one partial per block,
// gathered to every rank in gid order and combined in that order. Volume weights are the exact
// cell volumes (per cell in curvilinear coordinates).
#include <mpi.h>

#include <span>

#include "forest.hpp"

namespace remnant::grid {

struct BlockPartial {
  double value = 0;   // sum, min, max, Σ u dV, Σ |u| dV or Σ u² dV over the block's interior
  double volume = 0;  // Σ dV over the block's interior
};

BlockPartial block_partial(Block& block, int group, int comp, ReductionKind kind);
double combine(std::span<const BlockPartial> partials, ReductionKind kind);

// `blocks` are this rank's blocks in gid order, as `layout` distributes them.
double reduce_blocks(std::span<Block* const> blocks, const Forest& layout, int group, int comp,
                     ReductionKind kind, MPI_Comm comm);

}  // namespace remnant::grid
