#pragma once
// Which blocks exist, where they sit, their order along the space-filling curve (gid) and which
// rank owns each: everything about the block mesh that needs no field data. The forest holds only
// leaves (the blocks that carry data), at levels 0..max_level; every rank holds the whole list.
// Level l has (cells per direction on level 0) * 2^l cells; all blocks have the same cell count.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "Grid/grid_config.hpp"
#include "remnant/domain.hpp"
#include "remnant/grid.hpp"

namespace remnant::grid {

using BlockIndex = std::array<std::int64_t, 3>;
using Offset = std::array<int, 3>;  // neighbour direction, each entry in {-1, 0, 1}

class Forest {
 public:
  // `config` must have passed checked(). The leaves are sorted along the curve: Morton order of
  // their position on the finest level present (contiguous chunks are compact rank domains).
  Forest(const GridConfig& config, std::vector<BlockKey> leaves, int nranks);
  // The blocks of level 0 (a uniform grid).
  static std::vector<BlockKey> base_level(const GridConfig& config);

  int dimension() const { return dimension_; }
  const std::array<int, 3>& block_cells() const { return block_cells_; }
  // Child c (0 or 1 per used direction) of the block at index K on the next level, and the points
  // it covers in K's level indices (half of K's range per used direction, plus the face points
  // where `stagger` is 1).
  struct ChildCover {
    std::array<std::int64_t, 3> index;
    GlobalBox cover;
  };
  ChildCover child_cover(const std::array<std::int64_t, 3>& K, const int (&c)[3], const std::array<int, 3>& stagger) const {
    ChildCover r{K, GlobalBox{}};
    for (std::size_t d = 0; d < 3; ++d) {
      if (static_cast<int>(d) >= dimension()) continue;
      r.index[d] = 2 * K[d] + c[d];
      r.cover.lo[d] = r.index[d] * block_cells_[d] / 2;
      r.cover.hi[d] = r.cover.lo[d] + block_cells_[d] / 2 + stagger[d];
    }
    return r;
  }
  // Global index (on the block's level) of the first interior cell of a block.
  std::array<std::int64_t, 3> origin(const BlockKey& k) const {
    std::array<std::int64_t, 3> o{};
    for (std::size_t d = 0; d < 3; ++d) o[d] = k.index[d] * block_cells_[d];
    return o;
  }
  // Blocks per direction on a level (1 in unused directions).
  BlockIndex blocks_on_level(int level) const;
  std::int64_t total_blocks() const { return static_cast<std::int64_t>(leaves_.size()); }
  const std::vector<BlockKey>& leaves() const { return leaves_; }
  const BlockKey& key(std::int64_t gid) const { return leaves_[static_cast<std::size_t>(gid)]; }
  // The gid of the leaf (level, index); -1 when it is not a leaf (refined, coarser or outside).
  std::int64_t find(int level, const BlockIndex& index) const;
  int finest_level() const { return finest_level_; }
  std::vector<std::int64_t> blocks_per_level() const;

  // Balanced contiguous chunks of the curve: rank r owns gids [first_gid(r), first_gid(r + 1)).
  int nranks() const { return nranks_; }
  std::int64_t first_gid(int rank) const;
  std::int64_t block_count(int rank) const { return first_gid(rank + 1) - first_gid(rank); }
  int owner(std::int64_t gid) const;

 private:
  struct KeyHash {
    std::size_t operator()(const BlockKey& k) const {
      std::uint64_t h = static_cast<std::uint64_t>(k.level);
      for (auto v : k.index) h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(v);
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };
  int dimension_;
  int nranks_;
  int finest_level_ = 0;
  std::array<int, 3> block_cells_{1, 1, 1};
  BlockIndex base_blocks_{1, 1, 1};
  std::vector<BlockKey> leaves_;
  std::unordered_map<BlockKey, std::int64_t, KeyHash> gid_of_;
};

// The 3^d - 1 neighbour directions of a d-dimensional grid, in a fixed order.
std::vector<Offset> neighbour_offsets(int dimension);

}  // namespace remnant::grid
