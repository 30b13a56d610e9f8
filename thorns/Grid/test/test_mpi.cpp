// The Grid on every rank of MPI_COMM_WORLD (run under mpirun -np 2): remote ghost messages fill
// ghosts exactly, and reductions give the same bits as the same grid on a single rank.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "grid_test_util.hpp"
#include "stagger_test_util.hpp"

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

GridConfig config(int dimension, Boundary lower, Boundary upper) {
  GridConfig c;
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

void expect_ghosts_right(const GridConfig& c) {
  TestGroups t = make_test_groups();
  AmrGrid grid(c, t.vars, MPI_COMM_WORLD);
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
  GridConfig c = config(3, Boundary::outflow, Boundary::reflect);
  c.boundary_lower[1] = c.boundary_upper[1] = Boundary::periodic;
  expect_ghosts_right(c);
}

TEST(GridMpi, TwoBlocksPeriodicOnTwoRanks) {
  // Each block's lower and upper neighbour is the same remote block: tags must tell them apart.
  GridConfig c = config(3, Boundary::periodic, Boundary::periodic);
  c.ncells = {16, 8, 8};
  c.block_size = {8, 8, 8};
  expect_ghosts_right(c);
}

TEST(GridMpi, RanksWithoutBlocks) {
  GridConfig c = config(2, Boundary::periodic, Boundary::periodic);
  c.ncells = {8, 8, 1};
  c.block_size = {8, 8, 1};
  expect_ghosts_right(c);
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  AmrGrid grid(c, vars, MPI_COMM_WORLD);
  for (Block* b : grid.local_blocks()) for_interior(*b, [&](int i, int j, int k) { b->field(u, 0)(i, j, k) = 1; });
  EXPECT_EQ(grid.reduce(u, 0, ReductionKind::sum), 64.0);
}

TEST(GridMpi, ReductionsAreBitwiseEqualToASingleRank) {
  TestGroups t = make_test_groups();
  const GridConfig c = config(3, Boundary::outflow, Boundary::outflow);
  AmrGrid shared(c, t.vars, MPI_COMM_WORLD);
  AmrGrid alone(c, t.vars, MPI_COMM_SELF);
  for (AmrGrid* g : {&shared, &alone}) fill_interior(*g, t.vars, t.vector);
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

// A refined mesh on all ranks and on one: the same ghosts (prolongation, restriction, mirrors
// across the axis and origin) and, after a regrid that moves blocks between ranks, the same bits.
TEST(GridMpi, RefinedMeshGivesTheSameBitsAsOneRank) {
  GridConfig c;
  c.coordinates = CoordinateSystem::spherical;
  c.dimension = 2;
  c.ncells = {32, 16, 1};
  c.block_size = {8, 8, 1};
  c.ghost_zones = 3;
  c.xmin = {0, 0, 0};
  c.xmax = {2, 3.141592653589793, 1};
  c.boundary_lower = {Boundary::origin, Boundary::axis, Boundary::outflow};
  c.boundary_upper = {Boundary::outflow, Boundary::axis, Boundary::outflow};
  c.max_level = 2;
  c.regions = {{RegionKind::shell, RegionMode::at_least, 2, {0.5, 0.9, 0, 0, 0, 0}}};
  TestGroups t = make_test_groups();
  AmrGrid shared(c, t.vars, MPI_COMM_WORLD);
  AmrGrid alone(c, t.vars, MPI_COMM_SELF);
  ASSERT_EQ(shared.all_blocks(), alone.all_blocks());
  const std::vector<int> groups = {t.scalar, t.vector, t.tensor_dd};
  for (AmrGrid* g : {&shared, &alone})
    for (int grp : groups)
      for (Block* b : g->local_blocks())
        for (int comp = 0; comp < t.vars.group(grp).ncomp(); ++comp)
          for_interior(*b, [&](int i, int j, int k) {
            const double r = b->centroid(0, i), th = b->centroid(1, j);
            b->field(grp, comp)(i, j, k) = (1 + comp) * std::exp(-4 * (r - 0.7) * (r - 0.7)) * (1 + 0.3 * std::cos(th));
          });
  // Refine every level-0 block (blocks move between ranks), then compare everything.
  std::vector<BlockKey> leaves;
  for (const BlockKey& k : shared.all_blocks())
    if (k.level == 0) {
      for (int c1 = 0; c1 < 2; ++c1)
        for (int c0 = 0; c0 < 2; ++c0) leaves.push_back({1, {2 * k.index[0] + c0, 2 * k.index[1] + c1, 0}});
    } else {
      leaves.push_back(k);
    }
  EXPECT_TRUE(shared.set_leaves(leaves));
  EXPECT_TRUE(alone.set_leaves(leaves));
  for (AmrGrid* g : {&shared, &alone}) g->synchronize(groups);
  for (int grp : groups)
    for (int comp = 0; comp < t.vars.group(grp).ncomp(); ++comp)
      for (ReductionKind k : {ReductionKind::volume_integral, ReductionKind::norm2, ReductionKind::maximum})
        EXPECT_EQ(shared.reduce(grp, comp, k), alone.reduce(grp, comp, k)) << to_string(k);
  // Ghosts too: every local block of the shared grid equals the same block of the single-rank grid.
  std::int64_t different = 0;
  for (Block* b : shared.local_blocks()) {
    Block* twin = alone.local_blocks()[static_cast<std::size_t>(b->gid)];
    for (int grp : groups)
      for (std::size_t p = 0; p < b->size(grp); ++p)
        if (std::memcmp(&b->data(grp)[p], &twin->data(grp)[p], sizeof(double)) != 0) ++different;
  }
  EXPECT_EQ(global_sum(different), 0);
}

// Staggered B in 3D curvilinear coordinates on all ranks and on one: regrids (prolongation that
// takes kept neighbours' faces, which may live on another rank) and correct_edges (both passes
// across ranks) followed by a CT update give the same bits.
TEST(GridMpi, StaggeredRegridAndEdgeCorrectionGiveTheSameBitsAsOneRank) {
  for (const CoordinateSystem coords : {CoordinateSystem::cylindrical, CoordinateSystem::spherical}) {
    EdgeSetup s;
    const GridConfig c = stagger_config(coords, 3);
    AmrGrid shared(c, s.f.vars, MPI_COMM_WORLD);
    AmrGrid alone(c, s.f.vars, MPI_COMM_SELF);
    std::vector<BlockKey> slab, grown;
    for (const BlockKey& k : alone.all_blocks())
      for (auto* out : {&slab, &grown}) {
        const bool refine = k.index[0] == 0 || (out == &grown && k.index[0] == 1);
        if (!refine) {
          out->push_back(k);
          continue;
        }
        for (int c2 = 0; c2 < 2; ++c2)
          for (int c1 = 0; c1 < 2; ++c1)
            for (int c0 = 0; c0 < 2; ++c0)
              out->push_back({1, {2 * k.index[0] + c0, 2 * k.index[1] + c1, 2 * k.index[2] + c2}});
      }
    for (AmrGrid* g : {&shared, &alone}) {
      ASSERT_TRUE(g->set_leaves(slab));
      fill_curl_of_random_potential(*g, s.f, 1, 99);
      ASSERT_TRUE(g->set_leaves(grown));
      fill_emf(*g, s);
      const std::vector<int> edges = {s.edge[0], s.edge[1], s.edge[2]};
      g->correct_edges(edges);
      ct_update(*g, s, 0.05);
    }
    std::int64_t differ = 0, compared = 0;
    for (Block* b : shared.local_blocks()) {
      Block* a = alone.local_blocks()[static_cast<std::size_t>(b->gid)];
      for (int d = 0; d < 3; ++d)
        for (int g : {s.f.group[d], s.edge[d]})
          for (std::size_t p = 0; p < b->size(g); ++p) {
            const double x = b->data(g)[p], y = a->data(g)[p];
            if (std::isnan(x) && std::isnan(y)) continue;
            ++compared;
            if (std::memcmp(&x, &y, sizeof x) != 0 && ++differ <= 3)
              ADD_FAILURE() << to_string(coords) << " block " << b->gid << " group " << g << " point " << p << ": " << x
                            << " vs " << y;
          }
    }
    EXPECT_EQ(global_sum(differ), 0) << to_string(coords);
    EXPECT_GT(global_sum(compared), 0);
    EXPECT_LE(divergence_stats(shared, s.f).scaled, 1e-13);
  }
}

// 2D, periodic, two level-0 blocks along y (the same neighbour beyond both y faces, as in the
// field loop): correct_edges on two ranks gives every edge the bits of one rank, where every copy
// of an edge has one value (E_x and E_y included, which the 2D CT update of B^3 reads).
TEST(GridMpi, EdgeCorrectionAcrossBothPeriodicFacesOfOneNeighbour) {
  EdgeSetup s;
  GridConfig c = stagger_config(CoordinateSystem::cartesian, 2);
  c.ncells = {32, 16, 1};
  c.max_level = 1;
  c.boundary_lower = c.boundary_upper = {Boundary::periodic, Boundary::periodic, Boundary::outflow};
  c.regions = {{RegionKind::box, RegionMode::at_least, 1, {-0.1, 0.1, -0.1, 0.1, -1, 1}}};
  AmrGrid shared(c, s.f.vars, MPI_COMM_WORLD);
  AmrGrid alone(c, s.f.vars, MPI_COMM_SELF);
  ASSERT_EQ(shared.finest_level(), 1);
  const std::vector<int> edges = {s.edge[0], s.edge[1], s.edge[2]};
  for (AmrGrid* g : {&shared, &alone}) {
    fill_distinct_edges(*g, s);
    g->correct_edges(edges);
  }
  EXPECT_EQ(edge_copy_mismatch(alone, s), 0.0);
  std::int64_t differ = 0;
  for (Block* b : shared.local_blocks()) {
    Block* a = alone.local_blocks()[static_cast<std::size_t>(b->gid)];
    for (int g : edges)
      for (std::size_t p = 0; p < b->size(g); ++p)
        if (std::memcmp(&b->data(g)[p], &a->data(g)[p], sizeof(double)) != 0) ++differ;
  }
  EXPECT_EQ(global_sum(differ), 0);
}

}  // namespace
}  // namespace remnant::grid::test
