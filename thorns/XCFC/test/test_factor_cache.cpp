// Line factors kept between solves (src/multigrid/factor_cache.hpp): one Multigrid solving the xCFC
// sequence of equations in turn (vector components with their angular modes and parities, chi, a
// lapse-type equation with a matter coefficient) must give exactly the bits of a fresh Multigrid
// per solve, while reusing the factors of the geometry-only equations.
#include <gtest/gtest.h>

#include <cmath>

#include "XCFC/multigrid/multigrid.hpp"
#include "XCFC/vector_poisson.hpp"
#include "spherical_octant.hpp"
#include "same_bits.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using test::same_bits;

GridShape spherical_2d() { return test::spherical_octant_2d(64, 16, 20.0); }

// A smooth source of amplitude a (and a matter-like k for the lapse-type equation).
std::vector<double> bump(const GridShape& s, double a) {
  std::vector<double> v(s.cells());
  for (int j = 0; j < s.n[1]; ++j)
    for (int i = 0; i < s.n[0]; ++i) {
      const double r = s.centre(0, i), th = s.centre(1, j);
      v[static_cast<std::size_t>(i + s.n[0] * j)] = a * std::exp(-r * r / 16) * (1 + 0.3 * std::cos(2 * th));
    }
  return v;
}

TEST(XCFCFactorCache, SequenceOfEquationsMatchesFreshSolves) {
  const GridShape s = spherical_2d();
  SolveSettings set;
  set.tolerance = 1e-10;
  set.max_cycles = 40;
  ScalarEquation x = cartesian_component_equation(s, 0), z = cartesian_component_equation(s, 2), chi = chi_equation();
  ScalarEquation lapse;
  lapse.far_value = 1.0;
  lapse.k = bump(s, 0.05);
  Multigrid shared(s);
  // x and z differ only in their parities and angular modes: their factors must not be mixed up.
  int step = 0;
  for (ScalarEquation* eq : {&x, &z, &chi, &lapse, &x, &chi, &z, &lapse, &x}) {
    eq->s0 = bump(s, 1e-3 * (1 + 0.1 * ++step));
    std::vector<double> a(s.cells(), 0.0), b = a;
    Multigrid fresh(s);
    const SolveStats sa = shared.solve(*eq, a, set), sb = fresh.solve(*eq, b, set);
    EXPECT_TRUE(sa.converged) << "solve " << step;
    EXPECT_GT(sa.cycles, 1) << "solve " << step;
    EXPECT_EQ(sa.cycles, sb.cycles) << "solve " << step;
    EXPECT_TRUE(same_bits(a, b)) << "solve " << step << ": the reused factors changed the solution";
    EXPECT_TRUE(same_bits(sa.history, sb.history)) << "solve " << step;
  }
  // x, chi, z and x again: four reuses (the lapse-type equation is refactored every time).
  EXPECT_EQ(shared.reused_factorisations(), 4);
}

}  // namespace
