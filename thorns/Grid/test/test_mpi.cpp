// The Grid on every rank of MPI_COMM_WORLD (run under mpirun -np 2): remote ghost messages fill
// ghosts exactly, and reductions give the same bits as the same grid on a single rank.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <vector>

#include "grid_test_util.hpp"

namespace remnant::grid::test {
namespace {

int world_size() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

// A failure on any rank fails the test on every rank, so that mpirun reports it.
std::int64_t global_sum(std::int64_t v) {
  std::int64_t s = 0;
  MPI_Allreduce(&v, &s, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  return s;
}

UniformGridConfig config(int dimension, Boundary lower, Boundary upper) {
  UniformGridConfig c;
  c.dimension = dimension;
  c.ncells = {24, 16, 12};
  c.block_size = {8, 4, 4};  // 3 x 4 x 3 = 36 blocks, uneven over 2 ranks in Morton order
  c.ghost_zones = 3;
  c.xmin = {-1, -2, 0};
  c.xmax = {1, 2, 1};
  c.boundary_lower = {lower, lower, lower};
  c.boundary_upper = {upper, upper, upper};
  return c;
}

void expect_ghosts_right(const UniformGridConfig& c) {
  TestGroups t = make_test_groups();
  UniformGrid grid(c, t.vars, MPI_COMM_WORLD);
  const std::vector<int> groups = {t.scalar, t.vector, t.covector, t.axial, t.tensor_dd};
  for (int g : groups) fill_interior(grid, t.vars, g);
  grid.synchronize(groups);
  for (int g : groups)
    EXPECT_EQ(global_sum(count_wrong_points(grid, t.vars, g)), 0) << t.vars.group(g).full_name();
}

TEST(GridMpi, RunsOnMoreThanOneRank) { EXPECT_GE(world_size(), 2); }

TEST(GridMpi, PeriodicGhostsAcrossRanks) {
  for (int dim = 1; dim <= 3; ++dim) expect_ghosts_right(config(dim, Boundary::periodic, Boundary::periodic));
}

TEST(GridMpi, ReflectAndOutflowAcrossRanks) {
  expect_ghosts_right(config(3, Boundary::reflect, Boundary::outflow));
  UniformGridConfig c = config(3, Boundary::outflow, Boundary::reflect);
  c.boundary_lower[1] = c.boundary_upper[1] = Boundary::periodic;
  expect_ghosts_right(c);
}

TEST(GridMpi, TwoBlocksPeriodicOnTwoRanks) {
  // Each block's lower and upper neighbour is the same remote block: tags must tell them apart.
  UniformGridConfig c = config(3, Boundary::periodic, Boundary::periodic);
  c.ncells = {16, 8, 8};
  c.block_size = {8, 8, 8};
  expect_ghosts_right(c);
}

TEST(GridMpi, RanksWithoutBlocks) {
  UniformGridConfig c = config(2, Boundary::periodic, Boundary::periodic);
  c.ncells = {8, 8, 1};
  c.block_size = {8, 8, 1};
  expect_ghosts_right(c);
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  UniformGrid grid(c, vars, MPI_COMM_WORLD);
  for (Block* b : grid.local_blocks()) for_interior(*b, [&](int i, int j, int k) { b->field(u, 0)(i, j, k) = 1; });
  EXPECT_EQ(grid.reduce(u, 0, ReductionKind::sum), 64.0);
}

TEST(GridMpi, ReductionsAreBitwiseEqualToASingleRank) {
  TestGroups t = make_test_groups();
  const UniformGridConfig c = config(3, Boundary::outflow, Boundary::outflow);
  UniformGrid shared(c, t.vars, MPI_COMM_WORLD);
  UniformGrid alone(c, t.vars, MPI_COMM_SELF);
  for (UniformGrid* g : {&shared, &alone}) fill_interior(*g, t.vars, t.vector);
  for (int comp = 0; comp < 3; ++comp)
    for (ReductionKind k : {ReductionKind::minimum, ReductionKind::maximum, ReductionKind::sum,
                            ReductionKind::volume_integral, ReductionKind::norm1, ReductionKind::norm2}) {
      const double a = shared.reduce(t.vector, comp, k), b = alone.reduce(t.vector, comp, k);
      EXPECT_EQ(a, b) << to_string(k) << " of component " << comp;
      double a0 = a;
      MPI_Bcast(&a0, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
      EXPECT_EQ(a, a0) << "every rank has the same value";
    }
  EXPECT_NE(shared.describe().find("ranks       " + std::to_string(world_size())), std::string::npos) << shared.describe();
}

}  // namespace
}  // namespace remnant::grid::test
