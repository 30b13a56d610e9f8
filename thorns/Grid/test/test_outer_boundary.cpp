// Outer boundary conditions: outflow copies the nearest interior value, reflect mirrors with the
// parity of each tensor component; edges and corners come out as the product of both faces.
#include <gtest/gtest.h>
#include <mpi.h>

#include <vector>

#include "grid_test_util.hpp"

namespace remnant::grid::test {
namespace {

GridConfig box3d(Boundary lower, Boundary upper) {
  GridConfig c;
  c.ncells = {12, 8, 16};
  c.block_size = {4, 4, 8};
  c.ghost_zones = 3;
  c.xmin = {-1, -0.5, 0};
  c.xmax = {1, 0.5, 2};
  c.boundary_lower = {lower, lower, lower};
  c.boundary_upper = {upper, upper, upper};
  return c;
}

void expect_all_ghosts_right(const GridConfig& c) {
  TestGroups t = make_test_groups();
  AmrGrid grid(c, t.vars, MPI_COMM_SELF);
  const std::vector<int> groups = {t.scalar, t.vector, t.covector, t.axial, t.tensor_dd};
  for (int g : groups) fill_interior(grid, t.vars, g);
  grid.synchronize(groups);
  for (int g : groups)
    EXPECT_EQ(count_wrong_points(grid, t.vars, g), 0) << t.vars.group(g).full_name();
}

TEST(OuterBoundary, OutflowEverywhere) {
  expect_all_ghosts_right(box3d(Boundary::outflow, Boundary::outflow));
}

TEST(OuterBoundary, ReflectEverywhere) {
  expect_all_ghosts_right(box3d(Boundary::reflect, Boundary::reflect));
}

TEST(OuterBoundary, ReflectBelowOutflowAbove) {
  expect_all_ghosts_right(box3d(Boundary::reflect, Boundary::outflow));
}

TEST(OuterBoundary, MixedPerDirection) {
  GridConfig c = box3d(Boundary::outflow, Boundary::outflow);
  c.boundary_lower = {Boundary::reflect, Boundary::periodic, Boundary::outflow};
  c.boundary_upper = {Boundary::outflow, Boundary::periodic, Boundary::reflect};
  expect_all_ghosts_right(c);
}

TEST(OuterBoundary, OneAndTwoDimensions) {
  GridConfig c = box3d(Boundary::reflect, Boundary::outflow);
  c.dimension = 2;
  expect_all_ghosts_right(c);
  c.dimension = 1;
  expect_all_ghosts_right(c);
}

// The parities the reflect condition applied, checked against the tensor transformation law
// written out by hand (not through expand_tensor).
TEST(OuterBoundary, ReflectionParitiesFollowTheTensorType) {
  GridConfig c;
  c.dimension = 3;
  c.ncells = {4, 4, 4};
  c.block_size = {4, 4, 4};
  c.ghost_zones = 1;
  c.boundary_lower = {Boundary::reflect, Boundary::reflect, Boundary::reflect};
  TestGroups t = make_test_groups();
  AmrGrid grid(c, t.vars, MPI_COMM_SELF);
  Block& b = *grid.local_blocks()[0];
  const std::vector<int> groups = {t.scalar, t.vector, t.covector, t.axial, t.tensor_dd};
  for (int g : groups)
    for (int comp = 0; comp < t.vars.group(g).ncomp(); ++comp) b.field(g, comp)(0, 1, 1) = 1.0;
  grid.synchronize(groups);
  // Ghost (-1, 1, 1) mirrors (0, 1, 1) across the x face.
  auto x_parity = [&](int g, int comp) { return b.field(g, comp)(-1, 1, 1); };
  EXPECT_EQ(x_parity(t.scalar, 0), 1.0);
  for (int g : {t.vector, t.covector}) {
    EXPECT_EQ(x_parity(g, 0), -1.0) << "v^x flips";
    EXPECT_EQ(x_parity(g, 1), 1.0);
    EXPECT_EQ(x_parity(g, 2), 1.0);
  }
  EXPECT_EQ(x_parity(t.axial, 0), 1.0) << "B^x is even across an x face";
  EXPECT_EQ(x_parity(t.axial, 1), -1.0);
  EXPECT_EQ(x_parity(t.axial, 2), -1.0);
  // gamma_xx, gamma_xy, gamma_xz, gamma_yy, gamma_yz, gamma_zz
  const double tensor[6] = {1, -1, -1, 1, 1, 1};
  for (int comp = 0; comp < 6; ++comp) EXPECT_EQ(x_parity(t.tensor_dd, comp), tensor[comp]) << comp;
}

}  // namespace
}  // namespace remnant::grid::test

namespace remnant::grid::test {
namespace {

// GridDriver::add_outflow_condition: called once per block face on an outflow face of the domain,
// for its group only, after the zero-gradient copy (the ghost already equals the layer inside).
TEST(OuterBoundary, OutflowConditionRunsAfterTheCopyOnBoundaryFacesOnly) {
  TestGroups t = make_test_groups();
  const GridConfig c = box3d(Boundary::reflect, Boundary::outflow);
  AmrGrid grid(c, t.vars, MPI_COMM_SELF);
  const std::vector<int> groups = {t.scalar, t.vector};
  for (int g : groups) fill_interior(grid, t.vars, g);
  int calls = 0, copied = 0, lower = 0;
  grid.add_outflow_condition(t.scalar, [&](Block& b, int d, bool upper) {
    ++calls;
    lower += !upper;
    int ghost[3] = {0, 0, 0}, inside[3] = {0, 0, 0};
    ghost[d] = b.n[static_cast<std::size_t>(d)];
    inside[d] = b.n[static_cast<std::size_t>(d)] - 1;
    const Field f = b.field(t.scalar, 0);
    copied += f(ghost[0], ghost[1], ghost[2]) == f(inside[0], inside[1], inside[2]);
    const auto ud = static_cast<std::size_t>(d);
    EXPECT_EQ((b.index[ud] + 1) * c.block_size[ud], c.ncells[ud]);  // a block on the upper face
  });
  grid.synchronize(groups);
  // Blocks 3 x 2 x 2: 4 upper x faces, 6 upper y, 6 upper z; the lower faces reflect.
  EXPECT_EQ(calls, 16);
  EXPECT_EQ(copied, 16);
  EXPECT_EQ(lower, 0);
  EXPECT_EQ(count_wrong_points(grid, t.vars, t.scalar), 0);  // the condition changed nothing
}

}  // namespace
}  // namespace remnant::grid::test
