#pragma once
// Multilinear interpolation of a cell-centred field of one block (ghosts included, so they must be
// synchronised) at a point given in the block's coordinates. Cell centres are the midpoints of
// the faces, whose coordinates neighbouring blocks share bit for bit; at a vertex the result is the
// mean of the 2^d cells around it. Unused directions take their single cell.
#include "remnant/coordinates.hpp"
#include "remnant/grid.hpp"

namespace remnant::seed {

class CellInterpolator {
 public:
  CellInterpolator(const Block& b, Field f);
  double operator()(const Point3& x) const;

 private:
  const Block* b_;
  Field f_;
  bool used_[3];
};

}  // namespace remnant::seed
