// The communication tallies (remnant/comm_counters.hpp) of the Grid on two ranks against counts
// made by hand for a known block layout: the scaling model (utils/scaling_model) is fed by them.
#include <gtest/gtest.h>
#include <mpi.h>

#include <vector>

#include "grid_test_util.hpp"
#include "remnant/comm_counters.hpp"

namespace remnant::grid::test {
namespace {

comm::Tally tally(const char* kind, int level) {
  const auto& t = comm::tallies();
  const auto it = t.find(comm::Key{kind, level});
  return it == t.end() ? comm::Tally{} : it->second;
}

// 2 x 2 x 1 blocks of 8^3 cells, 3 ghost zones, outflow everywhere (no periodic images). Morton
// order puts blocks (0,0) and (1,0) on rank 0, (0,1) and (1,1) on rank 1. Each rank sends the
// other, in one message: two y faces (3 x 8 x 8 cells each) and the two diagonal xy edges
// ((0,0) -> (1,1) and (1,0) -> (0,1): 3 x 3 x 8 cells each): 528 points per component.
GridConfig two_by_two() {
  GridConfig c;
  c.dimension = 3;
  c.ncells = {16, 16, 8};
  c.block_size = {8, 8, 8};
  c.ghost_zones = 3;
  c.xmin = {0, 0, 0};
  c.xmax = {1, 1, 0.5};
  c.boundary_lower = {Boundary::outflow, Boundary::outflow, Boundary::outflow};
  c.boundary_upper = c.boundary_lower;
  return c;
}

TEST(GridCommCounters, GhostExchangeBytesOfATwoByTwoLayout) {
  int nranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  ASSERT_EQ(nranks, 2);
  TestGroups t = make_test_groups();
  AmrGrid grid(two_by_two(), t.vars, MPI_COMM_WORLD);
  ASSERT_EQ(grid.local_blocks().size(), 2u);
  for (const Block* b : grid.local_blocks()) EXPECT_EQ(b->index[1], rank);  // the layout assumed above
  comm::reset();
  const std::vector<int> scalar_and_vector = {t.scalar, t.vector};  // 1 + 3 components
  grid.synchronize(scalar_and_vector);
  grid.synchronize(std::vector<int>{t.scalar});
  constexpr long long kPoints = 2 * 3 * 8 * 8 + 2 * 3 * 3 * 8;
  const comm::Tally g = tally("ghost_exchange", 0);
  EXPECT_EQ(g.calls, 2);
  EXPECT_EQ(g.messages, 2);  // one per peer and exchange
  EXPECT_EQ(g.bytes, kPoints * (4 + 1) * 8);
  EXPECT_EQ(g.cells, 2 * kPoints);  // points per component
  EXPECT_EQ(g.pattern, comm::Pattern::p2p);

  // A reduction: every rank receives the other's two per-block partials (two doubles each).
  comm::reset();
  grid.reduce(t.scalar, 0, ReductionKind::sum);
  const comm::Tally r = tally("grid_reduction", -1);
  EXPECT_EQ(r.calls, 1);
  EXPECT_EQ(r.bytes, 2 * 2 * 8);
  EXPECT_EQ(r.pattern, comm::Pattern::allgather);
}

}  // namespace
}  // namespace remnant::grid::test
