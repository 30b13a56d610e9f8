#pragma once
// The value of a cell-centred variable at the cell nearest a point: the "centre" reduction of the
// TSV output. Deterministic for any rank count: among blocks that contain the point the finest
// level wins, then the nearest cell centre, then the lowest gid (ties).
#include <array>

#include "remnant/grid.hpp"

namespace remnant::io {

struct CellChoice {
  int contains = 0;                // 1 if the block contains the point
  int level = 0;
  double distance2 = 0;            // squared distance over the used directions
  std::int64_t gid = 0;
  std::array<int, 3> cell{0, 0, 0};
};

// Nearest cell of one block to `point` (coordinates of the grid; unused directions ignored).
CellChoice nearest_cell(const Block& b, const std::array<double, 3>& point, int dimension);
// True if a is the better choice.
bool better(const CellChoice& a, const CellChoice& b);

// Collective over grid.comm(): the value at the chosen cell, the same on every rank.
double value_at_point(GridDriver& grid, int group, int comp, const std::array<double, 3>& point);

}  // namespace remnant::io
