// 1D grids take direct line solves on level 0 (SolveSettings::direct_1d): a solve must neither
// restrict coefficients to the coarse levels nor factor their lines, and must give the bits of the
// full set-up. One Multigrid runs a sequence of equations (a lapse-type one with a matter
// coefficient, the radial vector component, chi), switching between direct solves and V-cycles, and
// is compared bit for bit with a fresh Multigrid per solve.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "XCFC/multigrid/multigrid.hpp"
#include "XCFC/vector_poisson.hpp"
#include "manufactured.hpp"
#include "same_bits.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using test::same_bits;

GridShape spherical_1d() {
  using B = Boundary;
  return test::make_shape(CoordinateSystem::spherical, 1, {128, 1, 1}, {0, 0, 0}, {20, std::numbers::pi, 2 * std::numbers::pi},
                          {{{B::origin, B::outer}, {B::outer, B::outer}, {B::outer, B::outer}}});
}

std::vector<double> bump(const GridShape& s, double a) {
  std::vector<double> v(s.cells());
  for (int i = 0; i < s.n[0]; ++i) v[static_cast<std::size_t>(i)] = a * std::exp(-s.centre(0, i) * s.centre(0, i) / 16);
  return v;
}

TEST(XCFCDirect1D, LineSolvesSetUpLevelZeroOnly) {
  const GridShape s = spherical_1d();
  ScalarEquation x = cartesian_component_equation(s, 0), chi = chi_equation(), lapse;
  lapse.far_value = 1.0;
  lapse.k = bump(s, 0.05);
  Multigrid shared(s);
  int step = 0;
  struct Solve {
    ScalarEquation* eq;
    bool direct;
  };
  for (const Solve& sv : {Solve{&lapse, true}, Solve{&x, true}, Solve{&chi, true}, Solve{&lapse, false}, Solve{&x, false},
                          Solve{&lapse, true}, Solve{&x, true}, Solve{&chi, false}, Solve{&chi, true}}) {
    sv.eq->s0 = bump(s, 1e-3 * (1 + 0.1 * ++step));
    SolveSettings set;
    set.tolerance = 1e-10;
    set.max_cycles = 40;
    set.direct_1d = sv.direct;
    std::vector<double> a(s.cells(), 0.0), b = a;
    Multigrid fresh(s);
    const SolveStats sa = shared.solve(*sv.eq, a, set), sb = fresh.solve(*sv.eq, b, set);
    EXPECT_TRUE(sa.converged) << "solve " << step;
    EXPECT_EQ(sa.cycles, sb.cycles) << "solve " << step;
    EXPECT_TRUE(same_bits(a, b)) << "solve " << step;
    EXPECT_TRUE(same_bits(sa.history, sb.history)) << "solve " << step;
    if (sv.direct) {
      EXPECT_EQ(sa.restricted_cells, 0) << "solve " << step << ": a line solve restricted to coarse levels";
      // Matter coefficient: only level 0's lines (the geometry-only ones come from the factor cache).
      if (sv.eq == &lapse) EXPECT_EQ(sa.factored_cells, s.n[0]) << "solve " << step;
    } else {
      EXPECT_GT(sa.restricted_cells, 0) << "solve " << step;
    }
  }
}

}  // namespace
