#pragma once
// Per-level, per-direction 1D geometry of the cells by global index (ghosts beyond the domain
// included), computed once with the same formulas as Block::set_geometry so that the prolongation
// and restriction kernels, which may work from a message buffer without the source block, see
// the same bits on every rank.
#include <array>
#include <cstdint>
#include <vector>

#include "Grid/grid_config.hpp"

namespace remnant::grid {

class LevelGeometry {
 public:
  LevelGeometry(const GridConfig& config, int max_level);
  // Centroid and 1D volume weight of global cell i of `level` in direction d.
  double centroid(int level, int d, std::int64_t i) const { return at(level, d).centroid[index(level, d, i)]; }
  double weight(int level, int d, std::int64_t i) const { return at(level, d).weight[index(level, d, i)]; }
  double spacing(int level, int d) const { return at(level, d).dx; }

 private:
  struct Direction {
    double dx = 0;
    std::int64_t first = 0;
    std::vector<double> centroid, weight;
  };
  const Direction& at(int level, int d) const {
    return levels_[static_cast<std::size_t>(level)][static_cast<std::size_t>(d)];
  }
  std::size_t index(int level, int d, std::int64_t i) const {
    return static_cast<std::size_t>(i - at(level, d).first);
  }
  std::vector<std::array<Direction, 3>> levels_;
};

}  // namespace remnant::grid
