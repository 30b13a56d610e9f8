// Ghost exchange between blocks on one rank: every ghost (faces, edges, corners) of a periodic
// grid holds exactly the value of its periodic image.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <vector>

#include "grid_test_util.hpp"

namespace remnant::grid::test {
namespace {

struct PeriodicCase {
  int dimension;
  std::array<std::int64_t, 3> ncells;
  std::array<int, 3> block_size;
  int ghosts;
};

class PeriodicExchange : public ::testing::TestWithParam<PeriodicCase> {};

TEST_P(PeriodicExchange, GhostsHoldThePeriodicImageExactly) {
  const PeriodicCase& p = GetParam();
  GridConfig c;
  c.dimension = p.dimension;
  c.ncells = p.ncells;
  c.block_size = p.block_size;
  c.ghost_zones = p.ghosts;
  c.xmin = {-1, 0, 2};
  c.xmax = {1, 3, 2.5};
  for (std::size_t d = 0; d < 3; ++d) c.boundary_lower[d] = c.boundary_upper[d] = Boundary::periodic;
  TestGroups t = make_test_groups();
  AmrGrid grid(c, t.vars, MPI_COMM_SELF);
  const std::vector<int> groups = {t.scalar, t.vector, t.tensor_dd};
  for (int g : groups) fill_interior(grid, t.vars, g);
  grid.synchronize(groups);
  for (int g : groups) EXPECT_EQ(count_wrong_points(grid, t.vars, g), 0) << "group " << g;
}

INSTANTIATE_TEST_SUITE_P(
    Grid, PeriodicExchange,
    ::testing::Values(PeriodicCase{1, {32, 1, 1}, {8, 1, 1}, 3},
                      PeriodicCase{1, {12, 1, 1}, {4, 1, 1}, 4},  // ghosts as wide as a block
                      PeriodicCase{1, {8, 1, 1}, {8, 1, 1}, 2},   // one block: its own neighbour
                      PeriodicCase{2, {16, 12, 1}, {4, 4, 1}, 3},
                      PeriodicCase{2, {16, 8, 1}, {16, 4, 1}, 2},  // one block wide in x
                      PeriodicCase{3, {16, 16, 16}, {8, 8, 8}, 3},  // two blocks: both sides same neighbour
                      PeriodicCase{3, {12, 8, 20}, {4, 8, 4}, 3}),
    [](const ::testing::TestParamInfo<PeriodicCase>& info) {
      const auto& p = info.param;
      return std::to_string(p.dimension) + "D_" + std::to_string(p.ncells[0]) + "x" +
             std::to_string(p.ncells[1]) + "x" + std::to_string(p.ncells[2]) + "_blocks" +
             std::to_string(p.block_size[0]) + "x" + std::to_string(p.block_size[1]) + "x" +
             std::to_string(p.block_size[2]) + "_ng" + std::to_string(p.ghosts);
    });

TEST(GhostExchange, OnlyTheRequestedGroupsChange) {
  GridConfig c;
  c.ncells = {16, 16, 16};
  c.block_size = {8, 8, 8};
  for (std::size_t d = 0; d < 3; ++d) c.boundary_lower[d] = c.boundary_upper[d] = Boundary::periodic;
  TestGroups t = make_test_groups();
  AmrGrid grid(c, t.vars, MPI_COMM_SELF);
  fill_interior(grid, t.vars, t.scalar);
  fill_interior(grid, t.vars, t.vector);
  const std::vector<int> only_scalar = {t.scalar};
  grid.synchronize(only_scalar);
  EXPECT_EQ(count_wrong_points(grid, t.vars, t.scalar), 0);
  Block& b = *grid.local_blocks()[0];
  EXPECT_TRUE(std::isnan(b.field(t.vector, 0)(-1, 0, 0))) << "vector ghosts were not requested";
}

TEST(GhostExchange, VertexCentredGroupsAreRefusedClearly) {
  GridConfig c;
  c.ncells = {16, 16, 16};
  c.block_size = {8, 8, 8};
  VariableRegistry vars;
  const int face = add_group(vars, "P", TensorKind::scalar, Centering::vertex);
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  const std::vector<int> groups = {face};
  try {
    grid.synchronize(groups);
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex-centred group 'Test::P' is not supported"),
              std::string::npos) << e.what();
  }
}

// A group declaring fewer ghosts than the Grid's (thorn.yaml `ghosts`) has none to synchronise.
TEST(GhostExchange, GroupsWithFewerGhostsAreRefusedClearly) {
  GridConfig c;
  c.ncells = {16, 16, 16};
  c.block_size = {8, 8, 8};
  VariableRegistry vars;
  const int flux = add_group(vars, "F", TensorKind::scalar, Centering::face_x);
  vars.group(flux).ghosts = 1;
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  const std::vector<int> groups = {flux};
  try {
    grid.synchronize(groups);
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("group 'Test::F' holds 1 ghost layers"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Grid::ghost_zones is 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace remnant::grid::test
