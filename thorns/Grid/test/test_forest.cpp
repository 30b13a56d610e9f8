// Block forest: Morton order (also across levels), balanced contiguous rank chunks.
#include <gtest/gtest.h>

#include <set>

#include "forest.hpp"
#include "config.hpp"
#include "morton.hpp"

namespace remnant::grid::test {
namespace {

GridConfig config3d(std::array<std::int64_t, 3> ncells, std::array<int, 3> bs) {
  GridConfig c;
  c.ncells = ncells;
  c.block_size = bs;
  c.ghost_zones = 1;
  return checked(c);
}

TEST(Forest, MortonOrderOnAPowerOfTwoGrid) {
  const GridConfig c = config3d({8, 8, 8}, {2, 2, 2});
  const Forest layout(c, Forest::base_level(c), 1);
  ASSERT_EQ(layout.total_blocks(), 64);
  EXPECT_EQ(layout.key(0).index, (BlockIndex{0, 0, 0}));
  EXPECT_EQ(layout.key(1).index, (BlockIndex{1, 0, 0}));
  EXPECT_EQ(layout.key(2).index, (BlockIndex{0, 1, 0}));
  EXPECT_EQ(layout.key(4).index, (BlockIndex{0, 0, 1}));
  EXPECT_EQ(layout.key(8).index, (BlockIndex{2, 0, 0}));
  EXPECT_EQ(layout.key(63).index, (BlockIndex{3, 3, 3}));
  for (std::int64_t gid = 0; gid < 64; ++gid) EXPECT_EQ(layout.find(0, layout.key(gid).index), gid);
}

TEST(Forest, NonPowerOfTwoCountsKeepZOrder) {
  GridConfig c;
  c.dimension = 2;
  c.ncells = {12, 20, 1};
  c.block_size = {4, 4, 1};
  c.ghost_zones = 2;
  const GridConfig k = checked(c);
  const Forest layout(k, Forest::base_level(k), 1);
  ASSERT_EQ(layout.total_blocks(), 15);
  std::set<BlockIndex> seen;
  for (std::int64_t gid = 0; gid < 15; ++gid) {
    seen.insert(layout.key(gid).index);
    if (gid > 0) EXPECT_LT(morton_key(layout.key(gid - 1).index), morton_key(layout.key(gid).index));
  }
  EXPECT_EQ(seen.size(), 15u);
}

TEST(Forest, BalancedContiguousChunks) {
  GridConfig c;
  c.dimension = 1;
  c.ncells = {10, 1, 1};
  c.block_size = {1, 1, 1};
  c.ghost_zones = 1;
  const GridConfig k = checked(c);
  const Forest layout(k, Forest::base_level(k), 3);
  EXPECT_EQ(layout.block_count(0), 4);
  EXPECT_EQ(layout.block_count(1), 3);
  EXPECT_EQ(layout.block_count(2), 3);
  EXPECT_EQ(layout.first_gid(3), 10);
  EXPECT_EQ(layout.owner(0), 0);
  EXPECT_EQ(layout.owner(3), 0);
  EXPECT_EQ(layout.owner(4), 1);
  EXPECT_EQ(layout.owner(9), 2);
  const Forest sparse(k, Forest::base_level(k), 16);  // more ranks than blocks: the last ones stay empty
  for (std::int64_t gid = 0; gid < 10; ++gid) EXPECT_EQ(sparse.owner(gid), gid);
  EXPECT_EQ(sparse.block_count(12), 0);
}

TEST(Forest, NeighbourOffsets) {
  EXPECT_EQ(neighbour_offsets(1).size(), 2u);
  EXPECT_EQ(neighbour_offsets(2).size(), 8u);
  EXPECT_EQ(neighbour_offsets(3).size(), 26u);
  const auto offsets = neighbour_offsets(3);
  const std::set<Offset> distinct(offsets.begin(), offsets.end());
  EXPECT_EQ(distinct.size(), 26u);
}

TEST(Forest, RefinedBlocksFollowTheCurveOfTheFinestLevel) {
  GridConfig c;
  c.dimension = 2;
  c.ncells = {16, 16, 1};
  c.block_size = {8, 8, 1};
  c.max_level = 1;
  const GridConfig k = checked(c);
  // Block (0, 0) refined into four children: they come first, in Z order, then the three others.
  std::vector<BlockKey> leaves = {{0, {1, 0, 0}}, {0, {0, 1, 0}}, {0, {1, 1, 0}}, {1, {0, 0, 0}},
                                  {1, {1, 0, 0}}, {1, {0, 1, 0}}, {1, {1, 1, 0}}};
  const Forest f(k, leaves, 2);
  ASSERT_EQ(f.total_blocks(), 7);
  EXPECT_EQ(f.key(0), (BlockKey{1, {0, 0, 0}}));
  EXPECT_EQ(f.key(3), (BlockKey{1, {1, 1, 0}}));
  EXPECT_EQ(f.key(4), (BlockKey{0, {1, 0, 0}}));
  EXPECT_EQ(f.find(1, {1, 0, 0}), 1);
  EXPECT_EQ(f.find(0, {0, 0, 0}), -1) << "refined: not a leaf";
  EXPECT_EQ(f.finest_level(), 1);
  EXPECT_EQ(f.blocks_per_level(), (std::vector<std::int64_t>{3, 4}));
  EXPECT_EQ(f.owner(3), 0);
  EXPECT_EQ(f.owner(4), 1);
}

}  // namespace
}  // namespace remnant::grid::test
