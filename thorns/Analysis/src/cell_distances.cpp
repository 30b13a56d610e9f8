#include "cell_distances.hpp"

#include <cmath>

#include "remnant/coordinates.hpp"

namespace remnant::analysis {

std::span<const double> CellDistances::of(std::span<Block* const> blocks, std::size_t p) {
  if (entries_.size() != blocks.size()) entries_.resize(blocks.size());
  const Block& b = *blocks[p];
  const Key key{b.coordinates, b.level, b.index, b.n, b.lo, b.dx};
  Entry& e = entries_[p];
  if (!e.filled || !(e.key == key)) {
    e.key = key;
    e.r.clear();
    e.r.reserve(static_cast<std::size_t>(b.n[0]) * static_cast<std::size_t>(b.n[1]) * static_cast<std::size_t>(b.n[2]));
    for_interior(b, [&](int i, int j, int k) {
      const Point3 X = coords::to_cartesian(b.coordinates, {b.centroid(0, i), b.centroid(1, j), b.centroid(2, k)});
      e.r.push_back(std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));
    });
    e.filled = true;
  }
  return e.r;
}

}  // namespace remnant::analysis
