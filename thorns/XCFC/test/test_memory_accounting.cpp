// Memory accounting of the multigrid's levels (issue 21, goal 7): bytes held per finest cell of a
// 3D Cartesian grid after a solve, all levels together. Measured 256.3 B/cell; before, every level
// also held three angular-mode coefficient arrays that are zero in 3D: 283.8 B/cell.
// Bound: measured + 5 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "XCFC/multigrid/multigrid.hpp"
#include "manufactured.hpp"

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;

TEST(XCFCMemory, MultigridLevelBytesPerCell3D) {
  using B = Boundary;
  const GridShape s = make_shape(CoordinateSystem::cartesian, 3, {32, 32, 32}, {0, 0, 0}, {8, 8, 8},
                                 {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::reflect, B::outer}}});
  Multigrid mg(s);
  ScalarEquation eq;
  eq.s0.assign(s.cells(), 0.0);
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const Point3 x = s.point(i, j, k);
    eq.s0[q] = -std::exp(-(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
  });
  eq.falloff = 1;
  std::vector<double> u(s.cells(), 0.0);
  SolveSettings set;
  set.tolerance = 1e-6;
  ASSERT_TRUE(mg.solve(eq, u, set).converged);
  const double per_cell = static_cast<double>(mg.stored_bytes()) / static_cast<double>(s.cells());
  std::printf("3D Cartesian 32^3 multigrid: %.1f bytes per finest cell\n", per_cell);
  EXPECT_LT(per_cell, 256.3 * 1.05);
  // The cell frames (Jacobian and metric diagonal) of a Cartesian grid are one entry, not 96 bytes
  // per ghosted point (115 B per finest cell here before).
  EXPECT_LT(mg.stored_bytes() - mg.level_bytes(), 1000);
}
