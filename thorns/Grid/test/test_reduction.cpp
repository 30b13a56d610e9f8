// Reductions: analytic values, and the same result for any block decomposition.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>

#include "grid_test_util.hpp"

namespace remnant::grid::test {
namespace {

// Sets component 0 of `group` to u(x, y, z) at cell centres.
template <class F>
void set_field(AmrGrid& grid, int group, F&& u) {
  for (Block* b : grid.local_blocks()) {
    Field f = b->field(group, 0);
    for_interior(*b, [&](int i, int j, int k) { f(i, j, k) = u(b->x(0, i), b->x(1, j), b->x(2, k)); });
  }
}

GridConfig cube(int n, int block) {
  GridConfig c;
  c.ncells = {n, n, n};
  c.block_size = {block, block, block};
  c.ghost_zones = 2;
  c.xmin = {-1, -1, -1};
  c.xmax = {1, 1, 1};
  return c;
}

TEST(Reduction, AnalyticValuesOnTheMidpointGrid) {
  const int n = 16;
  const double h = 2.0 / n;
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  AmrGrid grid(cube(n, 8), vars, MPI_COMM_SELF);

  set_field(grid, u, [](double, double, double) { return 1.0; });
  EXPECT_EQ(grid.reduce(u, 0, ReductionKind::sum), n * n * n);
  EXPECT_DOUBLE_EQ(grid.reduce(u, 0, ReductionKind::volume_integral), 8.0);
  EXPECT_DOUBLE_EQ(grid.reduce(u, 0, ReductionKind::norm1), 1.0);
  EXPECT_DOUBLE_EQ(grid.reduce(u, 0, ReductionKind::norm2), 1.0);

  set_field(grid, u, [](double x, double, double) { return x; });
  EXPECT_EQ(grid.reduce(u, 0, ReductionKind::minimum), -1 + h / 2);
  EXPECT_EQ(grid.reduce(u, 0, ReductionKind::maximum), 1 - h / 2);
  EXPECT_NEAR(grid.reduce(u, 0, ReductionKind::volume_integral), 0.0, 1e-14);
  // Midpoint sums: mean |x| = 1/2 exactly; mean x^2 = 1/3 - h^2/12.
  EXPECT_DOUBLE_EQ(grid.reduce(u, 0, ReductionKind::norm1), 0.5);
  EXPECT_DOUBLE_EQ(grid.reduce(u, 0, ReductionKind::norm2), std::sqrt(1.0 / 3 - h * h / 12));

  set_field(grid, u, [](double x, double y, double z) { return 2 + x * y + z; });
  EXPECT_DOUBLE_EQ(grid.reduce(u, 0, ReductionKind::volume_integral), 16.0);
}

TEST(Reduction, VolumesInOneAndTwoDimensions) {
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  GridConfig c = cube(16, 4);
  c.xmax = {3, 1, 1};  // x spans 4, y spans 2
  c.dimension = 2;
  {
    AmrGrid grid(c, vars, MPI_COMM_SELF);
    set_field(grid, u, [](double, double, double) { return 1.0; });
    EXPECT_DOUBLE_EQ(grid.reduce(u, 0, ReductionKind::volume_integral), 8.0);
  }
  c.dimension = 1;
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  set_field(grid, u, [](double, double, double) { return 1.0; });
  EXPECT_DOUBLE_EQ(grid.reduce(u, 0, ReductionKind::volume_integral), 4.0);
  EXPECT_EQ(grid.reduce(u, 0, ReductionKind::sum), 16.0);
}

TEST(Reduction, NaNIsNeverHiddenByMinOrMax) {
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  AmrGrid grid(cube(8, 4), vars, MPI_COMM_SELF);
  set_field(grid, u, [](double x, double, double) { return x; });
  grid.local_blocks()[3]->field(u, 0)(1, 2, 3) = std::nan("");
  EXPECT_TRUE(std::isnan(grid.reduce(u, 0, ReductionKind::minimum)));
  EXPECT_TRUE(std::isnan(grid.reduce(u, 0, ReductionKind::maximum)));
}

// Other block sizes sum in another order: min and max agree bit for bit, sums to rounding.
TEST(Reduction, IndependentOfTheBlockSize) {
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  auto profile = [](double x, double y, double z) { return std::exp(-x * x - 2 * y * y) * (1 + z) - 0.3; };
  AmrGrid coarse_blocks(cube(32, 16), vars, MPI_COMM_SELF);
  AmrGrid fine_blocks(cube(32, 4), vars, MPI_COMM_SELF);
  set_field(coarse_blocks, u, profile);
  set_field(fine_blocks, u, profile);
  for (ReductionKind k : {ReductionKind::minimum, ReductionKind::maximum})
    EXPECT_EQ(coarse_blocks.reduce(u, 0, k), fine_blocks.reduce(u, 0, k)) << to_string(k);
  for (ReductionKind k : {ReductionKind::sum, ReductionKind::volume_integral, ReductionKind::norm1,
                          ReductionKind::norm2}) {
    const double a = coarse_blocks.reduce(u, 0, k), b = fine_blocks.reduce(u, 0, k);
    EXPECT_NEAR(a, b, 1e-13 * std::abs(a)) << to_string(k);
  }
}

}  // namespace
}  // namespace remnant::grid::test
