// The per-block cache of cell distances from the origin (star_diagnostics' nearest cell): the
// values are |to_cartesian(centroid)| bit for bit, kept while a position holds the same block
// geometry and recomputed when another block takes that position (regrid, load balancing).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "cell_distances.hpp"
#include "remnant/coordinates.hpp"

namespace remnant::analysis {
namespace {

std::unique_ptr<Block> spherical_block(const VariableRegistry& vars, int level, std::int64_t index_r) {
  const double pi = std::numbers::pi;
  const std::array<double, 3> domain_lo{0, 0, 0};
  const std::array<double, 3> dx{0.1 / (1 << level), pi / 4 / (1 << level), 2 * pi / 8 / (1 << level)};
  const std::array<int, 3> n{4, 4, 8};
  std::array<double, 3> lo{index_r * n[0] * dx[0], 0, 0};
  auto b = std::make_unique<Block>(0, level, std::array<std::int64_t, 3>{index_r, 0, 0}, n, std::array<int, 3>{2, 2, 2},
                                   lo, dx, vars);
  b->set_geometry(CoordinateSystem::spherical, domain_lo);
  return b;
}

void expect_exact(const Block& b, std::span<const double> r) {
  ASSERT_EQ(r.size(), static_cast<std::size_t>(b.n[0] * b.n[1] * b.n[2]));
  std::size_t p = 0;
  for_interior(b, [&](int i, int j, int k) {
    const Point3 X = coords::to_cartesian(b.coordinates, {b.centroid(0, i), b.centroid(1, j), b.centroid(2, k)});
    EXPECT_EQ(r[p++], std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));  // bit-identical
  });
}

TEST(CellDistances, ExactValuesCachedPerBlockAndRecomputedAfterRegrid) {
  VariableRegistry vars;
  auto a = spherical_block(vars, 0, 0), c = spherical_block(vars, 0, 1);
  std::vector<Block*> blocks{a.get(), c.get()};
  CellDistances cache;
  const double* first = cache.of(blocks, 0).data();
  expect_exact(*a, cache.of(blocks, 0));
  expect_exact(*c, cache.of(blocks, 1));
  EXPECT_EQ(cache.of(blocks, 0).data(), first);  // the same block: no recomputation
  // A regrid: position 0 now holds a refined block, position 1 the old block a.
  auto fine = spherical_block(vars, 1, 0);
  blocks = {fine.get(), a.get()};
  expect_exact(*fine, cache.of(blocks, 0));
  expect_exact(*a, cache.of(blocks, 1));
  blocks = {a.get()};  // fewer blocks
  expect_exact(*a, cache.of(blocks, 0));
}

}  // namespace
}  // namespace remnant::analysis
