// Local relaxation next to the spherical origin in 2D (multigrid_smoothing.cpp, relax): the theta
// lines of every shell whose angular coupling exceeds the radial one (r dtheta < dr, i < 1/dtheta)
// get extra zebra passes. Without them the L-infinity residual of the migration grid's equations
// stalls at the origin after the first V-cycle (factors 0.1-0.25), which set the V-cycle count of
// the warm-started evolution solves. Mean factors on this grid: 0.138-0.145 before, 0.108-0.120 with.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "XCFC/multigrid/multigrid.hpp"
#include "XCFC/vector_poisson.hpp"
#include "spherical_octant.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;

// The migration grid's shape at half its radial resolution (r to 60, theta to pi/2).
GridShape migration_like() { return test::spherical_octant_2d(320, 32, 60.0); }

// A star-like source (radius 8) with an l = 2 part, solved from zero to 1e-9: the mean reduction
// per V-cycle of each xCFC equation type.
TEST(XCFCOriginRelaxation, VCycleFactorsNextToTheOrigin2D) {
  const GridShape s = migration_like();
  std::vector<double> src(s.cells());
  for (int j = 0; j < s.n[1]; ++j)
    for (int i = 0; i < s.n[0]; ++i) {
      const double r = s.centre(0, i), th = s.centre(1, j);
      src[static_cast<std::size_t>(i + s.n[0] * j)] = r < 8 ? 1e-3 * (1 - r * r / 64) * (1 + 0.5 * std::cos(2 * th)) : 0.0;
    }
  SolveSettings set;
  set.tolerance = 1e-9;
  set.max_cycles = 60;
  Multigrid mg(s);
  const char* names[] = {"x (m = 1)", "z", "chi"};
  const ScalarEquation eqs[] = {cartesian_component_equation(s, 0), cartesian_component_equation(s, 2), chi_equation()};
  for (int e = 0; e < 3; ++e) {
    ScalarEquation eq = eqs[e];
    eq.s0 = src;
    std::vector<double> u(s.cells(), 0.0);
    const SolveStats st = mg.solve(eq, u, set);
    std::printf("%-10s V-cycles %2d  mean factor %.3f\n", names[e], st.cycles, st.factor);
    EXPECT_TRUE(st.converged) << names[e];
    EXPECT_LT(st.factor, 0.13) << names[e] << ": " << st.cycles << " V-cycles";
  }
}

}  // namespace
