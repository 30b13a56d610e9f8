#pragma once
// Which blocks exist, where they sit, their order along the Morton curve (gid) and which rank
// owns each: everything about the block mesh that needs no field data. One level for now; levels
// add a per-level index space and a tree on top of the same curve.
#include <array>
#include <cstdint>
#include <vector>

#include "Grid/uniform_grid.hpp"

namespace remnant::grid {

using BlockIndex = std::array<std::int64_t, 3>;
using Offset = std::array<int, 3>;  // neighbour direction, each entry in {-1, 0, 1}

class BlockLayout {
 public:
  // `config` must have passed checked().
  BlockLayout(const UniformGridConfig& config, int nranks);

  int dimension() const { return dimension_; }
  const BlockIndex& blocks_per_direction() const { return nblocks_; }
  std::int64_t total_blocks() const { return static_cast<std::int64_t>(index_by_gid_.size()); }

  const BlockIndex& index_of(std::int64_t gid) const {
    return index_by_gid_[static_cast<std::size_t>(gid)];
  }
  std::int64_t gid_of(const BlockIndex& index) const;
  // The neighbour of `gid` across `offset`, wrapped in periodic directions; -1 beyond a
  // non-periodic domain face.
  std::int64_t neighbour(std::int64_t gid, const Offset& offset) const;
  bool at_lower_face(std::int64_t gid, int d) const { return index_of(gid)[static_cast<std::size_t>(d)] == 0; }
  bool at_upper_face(std::int64_t gid, int d) const {
    return index_of(gid)[static_cast<std::size_t>(d)] == nblocks_[static_cast<std::size_t>(d)] - 1;
  }

  // Balanced contiguous chunks of the curve: rank r owns gids [first_gid(r), first_gid(r + 1)).
  int nranks() const { return nranks_; }
  std::int64_t first_gid(int rank) const;
  std::int64_t block_count(int rank) const { return first_gid(rank + 1) - first_gid(rank); }
  int owner(std::int64_t gid) const;

 private:
  int dimension_;
  int nranks_;
  BlockIndex nblocks_{1, 1, 1};
  std::array<bool, 3> periodic_{false, false, false};
  std::vector<BlockIndex> index_by_gid_;
  std::vector<std::int64_t> gid_by_linear_index_;  // i + nx * (j + ny * k) -> gid
};

// The 3^d - 1 neighbour directions of a d-dimensional grid, in a fixed order.
std::vector<Offset> neighbour_offsets(int dimension);
// 0..26, unique per offset; used in message tags.
inline int offset_code(const Offset& o) { return (o[0] + 1) + 3 * (o[1] + 1) + 9 * (o[2] + 1); }

}  // namespace remnant::grid
