#pragma once
// Divergence-preserving prolongation of a face-normal vector (Balsara 2001, Toth & Roe 2002),
// written on the fluxes Phi = A B through the exact face areas of the Block geometry, so that it
// holds in Cartesian, cylindrical and spherical coordinates alike:
//  1. fine faces on a coarse face: B linear across the face (MC-limited tangential slopes of the
//     coarse face values), then shifted by a constant so that the fine fluxes sum to the coarse
//     flux (zero-area faces on an axis or the origin keep the coarse value and carry no flux);
//  2. fine faces inside a coarse cell: the mean of the two fine faces across, corrected by the
//     smallest change (least squares on the fluxes) that gives every fine cell the coarse cell's
//     divergence density. The correction solves the graph Laplacian of the 2^d fine cells
//     (a square or a cube), diagonal in the Walsh functions: no matrix, no division by zero.
// In 2D the correction is the one free constant per coarse cell of Toth & Roe; in 3D it also
// fixes the cross terms.
#include <span>

#include "face_vector.hpp"
#include "remnant/grid.hpp"

namespace remnant::grid {

// A block face of the child that a same-level block of the old mesh already has: the child takes
// that block's copy of the normal component (so that both copies agree), and its interior faces
// follow from it.
struct KeptFace {
  int direction = 0;
  bool upper = false;       // the child's upper face in `direction` (the neighbour's lower face)
  Block* neighbour = nullptr;
};

// Fills every interior face (the child's boundary faces included) of `vec` in `child` from
// `parent`, the block one level coarser that contains it, whose ghosts are current, and from the
// kept same-level neighbours.
void prolong_face_vector(Block& parent, Block& child, const FaceVector& vec, int dimension,
                         std::span<const KeptFace> kept = {});

}  // namespace remnant::grid
