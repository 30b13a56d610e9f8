#pragma once
// Moving the data of one mesh onto the next after a regrid: blocks that stay are copied (to
// whichever rank owns them now), new children are prolonged from their old parent, new parents
// restricted from their old children. Whole old blocks travel, one message per pair of ranks;
// every rank knows both meshes, so both sides agree on what moves without talking.
#include <mpi.h>

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "boundary_map.hpp"
#include "face_vector.hpp"
#include "forest.hpp"
#include "level_geometry.hpp"

namespace remnant::grid {

using BlockFactory = std::function<std::unique_ptr<Block>(std::int64_t gid, const BlockKey& key)>;

// `old_blocks`: this rank's blocks of `old_forest` in gid order, with current ghosts (the
// prolongation reads them). New children get the face vectors `face_vectors` by the
// divergence-preserving prolongation (taking the shared faces of same-level blocks that the old
// mesh had already, across periodic faces too), every other group by its transfer kernel.
// Returns this rank's blocks of `new_forest` in gid order. Collective. With `owned_old` (the
// owners of `old_blocks`, same order), unchanged blocks of this rank are moved out of it instead of
// copied (their pointers in `old_blocks` stay valid until the returned blocks are dropped).
std::vector<std::unique_ptr<Block>> migrate_blocks(const Forest& old_forest, std::span<Block* const> old_blocks,
                                                   const Forest& new_forest, const BlockFactory& make_new,
                                                   const BlockFactory& make_scratch, const VariableRegistry& vars,
                                                   const LevelGeometry& geometry, const BoundaryMaps& maps,
                                                   std::span<const FaceVector> face_vectors, int rank, MPI_Comm comm,
                                                   std::vector<std::unique_ptr<Block>>* owned_old = nullptr);

}  // namespace remnant::grid
