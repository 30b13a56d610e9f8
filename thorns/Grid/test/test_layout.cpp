// Block layout: Morton order, neighbours with periodic wrap, balanced contiguous rank chunks.
#include <gtest/gtest.h>

#include <set>

#include "block_layout.hpp"
#include "config.hpp"
#include "morton.hpp"

namespace remnant::grid::test {
namespace {

UniformGridConfig config3d(std::array<std::int64_t, 3> ncells, std::array<int, 3> bs) {
  UniformGridConfig c;
  c.ncells = ncells;
  c.block_size = bs;
  c.ghost_zones = 1;
  return checked(c);
}

TEST(BlockLayout, MortonOrderOnAPowerOfTwoGrid) {
  const BlockLayout layout(config3d({8, 8, 8}, {2, 2, 2}), 1);
  ASSERT_EQ(layout.total_blocks(), 64);
  EXPECT_EQ(layout.index_of(0), (BlockIndex{0, 0, 0}));
  EXPECT_EQ(layout.index_of(1), (BlockIndex{1, 0, 0}));
  EXPECT_EQ(layout.index_of(2), (BlockIndex{0, 1, 0}));
  EXPECT_EQ(layout.index_of(4), (BlockIndex{0, 0, 1}));
  EXPECT_EQ(layout.index_of(8), (BlockIndex{2, 0, 0}));
  EXPECT_EQ(layout.index_of(63), (BlockIndex{3, 3, 3}));
  for (std::int64_t gid = 0; gid < 64; ++gid) EXPECT_EQ(layout.gid_of(layout.index_of(gid)), gid);
}

TEST(BlockLayout, NonPowerOfTwoCountsKeepZOrder) {
  UniformGridConfig c;
  c.dimension = 2;
  c.ncells = {12, 20, 1};
  c.block_size = {4, 4, 1};
  c.ghost_zones = 2;
  const BlockLayout layout(checked(c), 1);
  ASSERT_EQ(layout.total_blocks(), 15);
  std::set<BlockIndex> seen;
  for (std::int64_t gid = 0; gid < 15; ++gid) {
    seen.insert(layout.index_of(gid));
    if (gid > 0) EXPECT_LT(morton_key(layout.index_of(gid - 1)), morton_key(layout.index_of(gid)));
  }
  EXPECT_EQ(seen.size(), 15u);
}

TEST(BlockLayout, NeighboursWrapOnlyInPeriodicDirections) {
  UniformGridConfig c;
  c.ncells = {8, 8, 8};
  c.block_size = {4, 4, 4};
  c.boundary_lower[0] = c.boundary_upper[0] = Boundary::periodic;
  const BlockLayout layout(checked(c), 1);
  const std::int64_t origin = layout.gid_of({0, 0, 0});
  EXPECT_EQ(layout.neighbour(origin, {-1, 0, 0}), layout.gid_of({1, 0, 0}));
  EXPECT_EQ(layout.neighbour(origin, {0, -1, 0}), -1);
  EXPECT_EQ(layout.neighbour(origin, {1, 1, 1}), layout.gid_of({1, 1, 1}));
  EXPECT_EQ(layout.neighbour(origin, {-1, 1, 0}), layout.gid_of({1, 1, 0}));
}

TEST(BlockLayout, BalancedContiguousChunks) {
  UniformGridConfig c;
  c.dimension = 1;
  c.ncells = {10, 1, 1};
  c.block_size = {1, 1, 1};
  c.ghost_zones = 1;
  const BlockLayout layout(checked(c), 3);
  EXPECT_EQ(layout.block_count(0), 4);
  EXPECT_EQ(layout.block_count(1), 3);
  EXPECT_EQ(layout.block_count(2), 3);
  EXPECT_EQ(layout.first_gid(3), 10);
  EXPECT_EQ(layout.owner(0), 0);
  EXPECT_EQ(layout.owner(3), 0);
  EXPECT_EQ(layout.owner(4), 1);
  EXPECT_EQ(layout.owner(9), 2);
  const BlockLayout sparse(checked(c), 16);  // more ranks than blocks: the last ones stay empty
  for (std::int64_t gid = 0; gid < 10; ++gid) EXPECT_EQ(sparse.owner(gid), gid);
  EXPECT_EQ(sparse.block_count(12), 0);
}

TEST(BlockLayout, NeighbourOffsets) {
  EXPECT_EQ(neighbour_offsets(1).size(), 2u);
  EXPECT_EQ(neighbour_offsets(2).size(), 8u);
  EXPECT_EQ(neighbour_offsets(3).size(), 26u);
  std::set<int> codes;
  for (const auto& o : neighbour_offsets(3)) codes.insert(offset_code(o));
  EXPECT_EQ(codes.size(), 26u);
}

}  // namespace
}  // namespace remnant::grid::test
