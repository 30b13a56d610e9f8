// The xCFC system's pointwise work on several ranks (CellShare): the equation coefficients, the
// shift source, A^ij and the vector transformations are computed by each rank for its share of the
// cells and gathered. The whole sequence X -> A^ij -> psi -> alpha psi -> beta solved with
// MPI_COMM_WORLD must give the bits of the MPI_COMM_SELF solve (a wrong or missing share leaves
// cells that differ), and each of 2 ranks must compute about half of the cells that one rank does.
// Run on 2 ranks by the ctest XCFC.mpi2 (and on one rank by the plain test program).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <tuple>

#include "XCFC/xcfc_system.hpp"
#include "manufactured.hpp"
#include "refined_layouts.hpp"
#include "same_bits.hpp"
#include "spherical_octant.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;

struct Sources {
  CompositeField E, S_trace;
  VectorField S_dn;
};

// A rotating, contracting blob: E~ and S~ Gaussian, S~_j with toroidal and poloidal parts, and a
// drift (a net momentum along x: the vector solves' monopole) of `drift`.
Sources sources(CompositeMultigrid& mg, double drift = 0.0) {
  Sources src{mg.field(), mg.field(), {mg.field(), mg.field(), mg.field()}};
  for (int n = 0; n < mg.parts(); ++n) {
    const GridShape& s = mg.part(n).shape;
    for_cells(s, [&](std::size_t q, int i, int j, int k) {
      const Point3 x = s.point(i, j, k), X = coords::to_cartesian(s.coordinates, x);
      const double g = std::exp(-0.4 * (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));
      src.E.part[n][q] = 2e-2 * g;
      src.S_trace.part[n][q] = 3e-3 * g;
      const Point3 S = coords::covector_from_cartesian(s.coordinates, x, Point3{-1e-3 * X[0] * g - 2e-3 * X[1] * g + drift * g,
                                                                                 -1e-3 * X[1] * g + 2e-3 * X[0] * g,
                                                                                 -1e-3 * X[2] * g});
      for (int a = 0; a < 3; ++a) src.S_dn[a].part[n][q] = S[a];
    });
  }
  return src;
}

// Solves the whole sequence with `solver`; returns the state.
XcfcState solve(XcfcSolver& solver, XcfcStats& stats, double drift) {
  CompositeMultigrid& mg = solver.multigrid();
  const Sources src = sources(mg, drift);
  XcfcState st;
  SolveSettings set;
  set.tolerance = 1e-10;
  set.full_multigrid = true;
  solver.solve_conformal_factor(src.E, src.S_dn, st, stats, set);
  solver.solve_lapse_and_shift(src.E, src.S_dn, src.S_trace, st, stats, set);
  return st;
}

void check(const char* name, XcfcSolver& serial, XcfcSolver& parallel, double drift = 0.0) {
  XcfcStats ss, sp;
  const XcfcState a = solve(serial, ss, drift), b = solve(parallel, sp, drift);
  EXPECT_TRUE(ss.psi.converged && ss.alpha_psi.converged && ss.X.converged() && ss.beta.converged()) << name;
  EXPECT_EQ(ss.psi.cycles, sp.psi.cycles) << name;
  EXPECT_EQ(ss.alpha_psi.cycles, sp.alpha_psi.cycles) << name;
  EXPECT_TRUE(same_bits(a.psi, b.psi)) << name << ": psi";
  EXPECT_TRUE(same_bits(a.alpha_psi, b.alpha_psi)) << name << ": alpha psi";
  EXPECT_TRUE(same_bits(a.A2, b.A2)) << name << ": A_ij A^ij";
  for (int c = 0; c < 6; ++c) EXPECT_TRUE(same_bits(a.A[c], b.A[c])) << name << ": A^ij " << c;
  for (int d = 0; d < 3; ++d) {
    EXPECT_TRUE(same_bits(a.X[d], b.X[d])) << name << ": X " << d;
    EXPECT_TRUE(same_bits(a.beta[d], b.beta[d])) << name << ": beta " << d;
  }
  // The covered cells' restriction of a field (the grid bridge's gathers): each rank restricts its
  // own patches, the footprints are exchanged.
  CompositeField ca = a.alpha_psi, cb = a.alpha_psi;
  for (int n = 0; n < serial.multigrid().parts(); ++n)
    for (std::size_t q = 0; q < ca.part[n].size(); ++q)
      if (serial.multigrid().covered(n, q)) ca.part[n][q] = cb.part[n][q] = 0;
  serial.multigrid().fill_covered(ca);
  parallel.multigrid().fill_covered(cb);
  EXPECT_TRUE(same_bits(ca, cb)) << name << ": covered cells";
  long long refilled = 0;  // covered cells given their children's mean (alpha psi ~ 1: nonzero)
  for (int n = 0; n < serial.multigrid().parts(); ++n)
    for (std::size_t q = 0; q < cb.part[n].size(); ++q) refilled += serial.multigrid().covered(n, q) && cb.part[n][q] > 0.5;
  if (serial.multigrid().parts() > 1) EXPECT_GT(refilled, 0) << name;
  // The problem is not trivial: momenta give A^ij and a shift.
  double amax = 0, bmax = 0;
  for (const auto& p : a.A2.part)
    for (double v : p) amax = std::max(amax, v);
  for (const auto& p : a.beta[0].part)
    for (double v : p) bmax = std::max(bmax, std::abs(v));
  EXPECT_GT(amax, 0) << name;
  EXPECT_GT(bmax, 0) << name;
  // The shares: the ranks' cells add up to the whole, each computed about half of one rank's work.
  int rank = 0, nranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  const CellShare& sh = parallel.multigrid().share();
  long long mine = static_cast<long long>(sh.cells()), total = 0;
  MPI_Allreduce(&mine, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(static_cast<std::size_t>(total), sh.total()) << name;
  const double work = double(parallel.multigrid().share().computed() + parallel.multigrid().share(true).computed()) /
                      double(serial.multigrid().share().computed() + serial.multigrid().share(true).computed());
  EXPECT_GT(serial.multigrid().share().computed(), 0) << name;
  if (nranks == 1) EXPECT_EQ(work, 1.0) << name;
  if (nranks == 2) {
    EXPECT_NEAR(double(mine) / double(total), 0.5, 0.01) << name;
    EXPECT_NEAR(work, 0.5, 0.01) << name;
  }
  if (rank == 0)
    std::printf("xCFC system %-16s %d parts, bits equal to one rank; pointwise cells computed by rank 0 / one rank: %.3f\n",
                name, parallel.multigrid().parts(), work);
  // The vector solves' monopole (only with a drift: a net momentum): its sums over the leaf cells
  // go by rows split between the ranks and its charge terms by share, so the ranks' cells add up
  // to one rank's and each of 2 visits half (a rank summing or charging every cell visits all).
  if (drift == 0.0) return;
  for (const auto& [what, one, own] : {std::tuple{"X", ss.X.monopole_cells, sp.X.monopole_cells},
                                        std::tuple{"beta", ss.beta.monopole_cells, sp.beta.monopole_cells}}) {
    long long sum = 0;
    MPI_Allreduce(&own, &sum, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_GT(one, 0) << name << ": " << what << " has no monopole";
    EXPECT_EQ(sum, one) << name << ": " << what;
    if (nranks == 2) EXPECT_NEAR(double(own) / double(one), 0.5, 0.02) << name << ": " << what;
    if (rank == 0) std::printf("xCFC system %-16s %s monopole cells visited by rank 0 / one rank: %.3f\n", name, what, double(own) / double(one));
  }
}

TEST(XCFCMultigridMPI, SystemSpherical2D) {
  const GridShape s = spherical_octant_2d(64, 32, 8.0);
  XcfcSolver serial(s), parallel(s, MPI_COMM_WORLD);
  check("spherical 2D", serial, parallel);
}

TEST(XCFCMultigridMPI, SystemCompositeCartesian3D) {
  using B = Boundary;
  const GridShape s = make_shape(CoordinateSystem::cartesian, 3, {16, 16, 16}, {0, 0, 0}, {4, 4, 4},
                                 {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::reflect, B::outer}}});
  const CompositeLayout lay = nested_layout(s, {4, 4, 4}, {{{{0, 2}, {0, 2}, {0, 2}}}});
  XcfcSolver serial(lay), parallel(lay, MPI_COMM_WORLD);
  check("cartesian 3D AMR", serial, parallel);
}

// A half space (mirror at z = 0, outer faces elsewhere) refined at the centre, with a drift: B^x and
// B^y carry a monopole (even at the mirror), split off by the unit charge.
TEST(XCFCMultigridMPI, SystemMonopoleSplitBetweenRanks) {
  using B = Boundary;
  const GridShape s = make_shape(CoordinateSystem::cartesian, 3, {16, 16, 8}, {-4, -4, 0}, {4, 4, 4},
                                 {{{B::outer, B::outer}, {B::outer, B::outer}, {B::reflect, B::outer}}});
  const CompositeLayout lay = nested_layout(s, {4, 4, 4}, {{{{-1, 1}, {-1, 1}, {0, 1}}}});
  XcfcSolver serial(lay), parallel(lay, MPI_COMM_WORLD);
  check("half space drift", serial, parallel, 2e-3);
}

}  // namespace
