#pragma once
// The Cartesian distance from the origin of every interior cell's centroid, per local block,
// cached between evaluations: it depends on the geometry only, and computing it (to_cartesian:
// sin/cos per cell) every step was 1.7 % of a 1D BU0 run. An entry is recomputed when the block at
// its position in local_blocks() is another one (regrid, load balancing): its key (coordinates,
// level, index, n, lo, dx) fixes the centroids. The values are those of
// |to_cartesian(centroid)| bit for bit, so the nearest cell (and ties) stay as before.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "remnant/grid.hpp"

namespace remnant::analysis {

class CellDistances {
 public:
  // Distances of the interior cells of blocks[p] (i fastest), valid until the next call.
  std::span<const double> of(std::span<Block* const> blocks, std::size_t p);

 private:
  struct Key {
    CoordinateSystem coordinates{};
    int level = 0;
    std::array<std::int64_t, 3> index{};
    std::array<int, 3> n{};
    std::array<double, 3> lo{}, dx{};
    bool operator==(const Key&) const = default;
  };
  struct Entry {
    Key key;
    bool filled = false;
    std::vector<double> r;
  };
  std::vector<Entry> entries_;
};

}  // namespace remnant::analysis
