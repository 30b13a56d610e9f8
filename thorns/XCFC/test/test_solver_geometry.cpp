// The geometry-only factors XcfcSolver keeps between solves (include/XCFC/solver_geometry.hpp): the
// kept Christoffel symbols are coords::christoffels' bits on every part of refined layouts in every
// coordinate system, the cache knows when a multigrid is not its own, and a solver whose multigrid
// was replaced (another refined layout: a regrid) gives A^ij bit-identical to a fresh solver's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "XCFC/solver_geometry.hpp"
#include "XCFC/xcfc_system.hpp"
#include "manufactured.hpp"
#include "refined_layouts.hpp"
#include "same_bits.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;

// Refined once inside the lower `fraction` of every used direction (whole angles on 3D curvilinear
// grids, as a star at the centre is refined).
CompositeLayout refined(const GridShape& g, double fraction) {
  Box b{};
  for (int d = 0; d < 3; ++d) {
    const double lo = g.lo[d], hi = g.lo[d] + g.n[d] * g.dx[d];
    const bool whole = g.dimension == 3 && coords::is_angle(g.coordinates, d);
    b[d] = {lo, whole ? hi : lo + fraction * (hi - lo)};
  }
  std::array<int, 3> pc{4, 4, 4};
  if (g.coordinates == CoordinateSystem::spherical && g.dimension == 2) b[1] = {g.lo[1], g.lo[1] + g.n[1] * g.dx[1]};
  return nested_layout(g, pc, {b});
}

TEST(XCFCSolverGeometry, ChristoffelsAreThoseOfTheCoordinates) {
  for (const Case& c : all_cases()) {
    SCOPED_TRACE(c.name);
    const CompositeLayout lay = refined(c.shape, 0.5);
    ASSERT_FALSE(lay.patches.empty());
    const CompositeMultigrid mg(lay);
    const SolverGeometry geo(mg);
    EXPECT_TRUE(geo.current_for(mg));
    EXPECT_EQ(geo.parts(), mg.parts());
    EXPECT_FALSE(geo.current_for(CompositeMultigrid(c.shape)));     // the unrefined base: fewer parts
    EXPECT_FALSE(geo.current_for(CompositeMultigrid(refined(c.shape, 0.75))));  // other patches
    long long cells = 0;
    for (int n = 0; n < mg.parts(); ++n) {
      const GridShape& s = mg.part(n).shape;
      // Cartesian parts store none (issue 21, memory): every symbol is zero there.
      const bool cartesian = s.coordinates == CoordinateSystem::cartesian;
      EXPECT_EQ(geo.christoffels(n).empty(), cartesian);
      for_part_cells(mg.part(n), [&](std::size_t q, std::size_t, int i, int j, int k) {
        const Christoffels want = coords::christoffels(s.coordinates, s.point(i, j, k));
        const Christoffels got = expand(cartesian ? CompactChristoffels{} : geo.christoffels(n)[q]);
        ASSERT_EQ(std::memcmp(&want, &got, sizeof want), 0) << "part " << n << " cell " << i << " " << j << " " << k;
        ++cells;
      });
    }
    EXPECT_GT(cells, static_cast<long long>(c.shape.cells()));
  }
}

// X potentials (Cartesian B, chi) of a smooth field on every part of mg.
XcfcState smooth_potentials(const CompositeMultigrid& mg) {
  XcfcState st;
  for (auto& B : st.X_potentials.B) B = mg.field();
  st.X_potentials.chi = mg.field();
  for (int n = 0; n < mg.parts(); ++n) {
    const GridShape& s = mg.part(n).shape;
    for_part_cells(mg.part(n), [&](std::size_t q, std::size_t, int i, int j, int k) {
      const Point3 X = coords::to_cartesian(s.coordinates, s.point(i, j, k));
      const double e = std::exp(-0.2 * (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));
      for (int a = 0; a < 3; ++a) st.X_potentials.B[a].part[n][q] = (0.3 + 0.1 * a) * X[a] * e;
      st.X_potentials.chi.part[n][q] = 0.05 * e * (1 + 0.2 * X[2]);
    });
  }
  return st;
}

TEST(XCFCSolverGeometry, RebuiltWhenTheMultigridIsReplaced) {
  for (const Case& c : all_cases()) {
    if (c.shape.dimension == 1 && c.shape.coordinates == CoordinateSystem::cartesian) continue;
    SCOPED_TRACE(c.name);
    const CompositeLayout before = refined(c.shape, 0.75), after = refined(c.shape, 0.5);
    XcfcSolver sv(before);
    XcfcState st = smooth_potentials(sv.multigrid());
    sv.vector_potential_from_warm_start(st);  // the geometry of `before` is now kept
    ASSERT_TRUE(sv.geometry().current_for(sv.multigrid()));
    sv.multigrid() = CompositeMultigrid(after);  // a regrid
    XcfcState moved = smooth_potentials(sv.multigrid());
    sv.vector_potential_from_warm_start(moved);
    XcfcSolver fresh(after);
    XcfcState want = smooth_potentials(fresh.multigrid());
    fresh.vector_potential_from_warm_start(want);
    for (int a = 0; a < 6; ++a) EXPECT_TRUE(same_bits(moved.A[a], want.A[a])) << "A component " << a;
    EXPECT_TRUE(same_bits(moved.A2, want.A2));
    // The A^ij of a curvilinear field involve the symbols: the test would see stale ones.
    double largest = 0;
    for (const auto& part : want.A2.part)
      for (double v : part) largest = std::max(largest, std::abs(v));
    EXPECT_GT(largest, 0.0);
  }
}

}  // namespace
