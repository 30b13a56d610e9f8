// What the distributed multigrid moves between ranks (work_partition.hpp): on a 2D spherical level
// split in theta slabs, the theta lines cross the slabs and are solved in a line split by radius.
// They reach it by a transpose (each rank receives about 1/P of the level per pass), not by making
// the whole level complete on every rank (each rank received (P-1)/P of it, twice per pass), and
// the origin's local relaxation gathers only its shells on rank 0.
// Measured as bytes received per V-cycle in units of the finest level's interior; the solution
// keeps the bits of one rank (XCFCMultigridMPI.Spherical2D). Run on 2 ranks by XCFC.mpi2; on one
// rank it checks that nothing is exchanged. The communication tallies (remnant/comm_counters.hpp)
// of a 3D Cartesian solve are checked against the halo planes counted by hand.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "XCFC/multigrid/multigrid.hpp"
#include "remnant/comm_counters.hpp"
#include "spherical_octant.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;

TEST(XCFCMultigridMPI, ExchangeVolume2D) {
  int nranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const GridShape s = remnant::xcfc::test::spherical_octant_2d(256, 32, 60.0);
  ScalarEquation eq;
  eq.far_value = 1.0;
  eq.k.assign(s.cells(), 0.0);
  for (int j = 0; j < s.n[1]; ++j)
    for (int i = 0; i < s.n[0]; ++i) {
      const double r = s.centre(0, i);
      eq.k[static_cast<std::size_t>(i + s.n[0] * j)] = r < 8 ? 0.05 * (1 - r * r / 64) * (1 + 0.2 * std::cos(2 * s.centre(1, j))) : 0.0;
    }
  SolveSettings set;
  set.tolerance = 1e-9;
  Multigrid mg(s, MPI_COMM_WORLD);
  ASSERT_EQ(mg.distributed_levels() > 0, nranks > 1);
  std::vector<double> u(s.cells(), 1.0);
  const long long before = mg.received_bytes();
  const SolveStats st = mg.solve(eq, u, set);
  ASSERT_TRUE(st.converged);
  const double level = 8.0 * static_cast<double>(s.cells());
  const double per_cycle = static_cast<double>(mg.received_bytes() - before) / st.cycles / level;
  if (rank == 0) std::printf("2D spherical 256 x 32 on %d ranks: %d V-cycles, received per V-cycle %.2f levels\n", nranks, st.cycles, per_cycle);
  if (nranks == 1) EXPECT_EQ(mg.received_bytes(), 0);  // one rank: nothing exchanged
  else EXPECT_LT(per_cycle, 4.5);  // 8.48 with whole-level Allgathers, 4.72 with transposes, 3.55 now
}

// 32^3 Cartesian on 2 ranks: levels 32^3 and 16^3 are split in k slabs (8^3 = 512 cells is below
// WorkPartition::kMinCells), so each halo exchange sends one ghosted plane, (n + 2)^2 values, to
// the one neighbour; the halo and gather bytes add up to the bytes the partition received.
// The tallies of one 32^3 solve; returns this rank's received bytes (nranks == 2).
long long check_tallies(MultigridStorage storage) {
  int nranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  GridShape s;
  s.coordinates = CoordinateSystem::cartesian;
  s.dimension = 3;
  s.n = {32, 32, 32};
  s.dx = {0.5, 0.5, 0.5};
  for (auto& b : s.boundary) b = {Boundary::reflect, Boundary::outer};
  ScalarEquation eq;
  eq.far_value = 1.0;
  eq.k.assign(s.cells(), 0.0);
  for (int k = 0; k < s.n[2]; ++k)
    for (int j = 0; j < s.n[1]; ++j)
      for (int i = 0; i < s.n[0]; ++i) {
        const double r2 = s.centre(0, i) * s.centre(0, i) + s.centre(1, j) * s.centre(1, j) + s.centre(2, k) * s.centre(2, k);
        eq.k[static_cast<std::size_t>(i + s.n[0] * (j + s.n[1] * k))] = r2 < 16 ? 0.05 * (1 - r2 / 16) : 0.0;
      }
  SolveSettings set;
  set.tolerance = 1e-8;
  Multigrid mg(s, MPI_COMM_WORLD, storage);
  std::vector<double> u(s.cells(), 1.0);
  comm::reset();
  const long long before = mg.received_bytes();
  EXPECT_TRUE(mg.solve(eq, u, set).converged);
  const auto& t = comm::tallies();
  auto tally = [&](const char* kind, int level) {
    const auto it = t.find(comm::Key{kind, level});
    return it == t.end() ? comm::Tally{} : it->second;
  };
  if (nranks == 1) {
    EXPECT_EQ(tally("mg_base_halo", 0).calls, 0);
    return 0;
  }
  EXPECT_EQ(nranks, 2);
  EXPECT_EQ(mg.distributed_levels(), 2);
  long long moved = 0;
  for (int l = 0; l < 3; ++l) {
    const comm::Tally h = tally("mg_base_halo", l);
    const long long n = 32 >> l;
    if (l < 2) {
      EXPECT_GT(h.calls, 0) << "level " << l;
      EXPECT_EQ(h.messages, h.calls) << "level " << l;
      EXPECT_EQ(h.bytes, h.calls * 8 * (n + 2) * (n + 2)) << "level " << l;
    } else {
      EXPECT_EQ(h.calls, 0) << "level " << l << " is not split";
    }
    moved += h.bytes + tally("mg_base_allgather", l).bytes;
  }
  EXPECT_EQ(moved, mg.received_bytes() - before);
  if (storage == MultigridStorage::distributed) {
    // No whole-level copies of the split levels: level 0 gathers only the solution for the
    // interface (the other rank's 16 interior planes, once), level 1 nothing; the 8^3 level below
    // the split is agglomerated from each rank's 4 planes.
    EXPECT_EQ(tally("mg_base_allgather", 0).bytes, 8LL * 32 * 32 * 16);
    EXPECT_EQ(tally("mg_base_allgather", 1).bytes, 0);
    EXPECT_GT(tally("mg_base_allgather", 2).calls, 0);
  } else {
    EXPECT_GT(tally("mg_base_allgather", 1).bytes, 0);  // the split coarse level made whole
  }
  return mg.received_bytes() - before;
}

TEST(XCFCMultigridMPI, CommTalliesOfA3DCartesianSolve) { check_tallies(MultigridStorage::replicated); }

// Distributed storage: the split levels exchange halos only, the whole-level gathers are gone (in 3D
// Cartesian most bytes are halos either way: measured 1.15 MB against 1.45 MB per rank, 0.79).
TEST(XCFCMultigridMPI, CommTalliesOfADistributedSolve) {
  const long long replicated = check_tallies(MultigridStorage::replicated);
  const long long distributed = check_tallies(MultigridStorage::distributed);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0 && replicated > 0)
    std::printf("32^3 solve, bytes received by rank 0 of 2: replicated %lld, distributed %lld (%.3f)\n", replicated,
                distributed, double(distributed) / double(replicated));
  if (replicated > 0) EXPECT_LT(distributed, replicated);
}

}  // namespace
