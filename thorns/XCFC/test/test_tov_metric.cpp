// The metric of a TOV star from the xCFC solver given the star's matter (densitised E~ = psi^6 E as
// a hand-off would import it, S~ = 3 psi^6 p with the solver's psi) against the exact isotropic TOV
// solution (thorns/TOV): second-order convergence of psi and alpha, 1D/2D/3D spherical, 2D/3D
// cylindrical, and refined grids.
#include <gtest/gtest.h>

#include <cmath>

#include "TOV/tov_solver.hpp"
#include "XCFC/xcfc_system.hpp"
#include "manufactured.hpp"
#include "refined_layouts.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;

struct Errors {
  double psi, alpha;
  int cycles;
};

// The star's metric on a (possibly refined) grid; errors over the leaf cells.
Errors solve_star(const tov::TovStar& star, const CompositeLayout& layout) {
  XcfcSolver solver(layout);
  CompositeMultigrid& mg = solver.multigrid();
  CompositeField E = mg.field(), p = mg.field(), psi_exact = mg.field(), alpha_exact = mg.field();
  VectorField S;
  for (auto& c : S) c = mg.field();
  for (int n = 0; n < mg.parts(); ++n) {
    const GridShape& s = mg.part(n).shape;
    for_cells(s, [&](std::size_t q, int i, int j, int k) {
      const Point3 X = coords::to_cartesian(s.coordinates, s.point(i, j, k));
      const tov::TovPoint t = star.at(std::hypot(X[0], X[1], X[2]));
      E.part[n][q] = std::pow(t.psi, 6) * t.rho * (1 + t.eps);
      p.part[n][q] = t.press;
      psi_exact.part[n][q] = t.psi;
      alpha_exact.part[n][q] = t.alpha;
    });
  }
  XcfcState st;
  XcfcStats stats;
  SolveSettings set;
  set.tolerance = 1e-11;
  set.full_multigrid = true;
  solver.solve_conformal_factor(E, S, st, stats, set);
  CompositeField Str = p;
  for (int n = 0; n < mg.parts(); ++n)
    for (std::size_t q = 0; q < Str.part[n].size(); ++q) Str.part[n][q] = 3 * std::pow(st.psi.part[n][q], 6) * p.part[n][q];
  solver.solve_lapse_and_shift(E, S, Str, st, stats, set);
  const CompositeField alpha = st.alpha();
  Errors e{0, 0, stats.psi.cycles + stats.alpha_psi.cycles};
  for (int n = 0; n < mg.parts(); ++n)
    for (std::size_t q = 0; q < Str.part[n].size(); ++q) {
      if (mg.covered(n, q)) continue;
      e.psi = std::max(e.psi, std::abs(st.psi.part[n][q] - psi_exact.part[n][q]));
      e.alpha = std::max(e.alpha, std::abs(alpha.part[n][q] - alpha_exact.part[n][q]));
    }
  EXPECT_TRUE(stats.psi.converged && stats.alpha_psi.converged);
  return e;
}

// Three resolutions of the base grid; with boxes, two refined levels around the star (the block
// size scaled with the resolution so that the refined regions stay put).
void expect_second_order(const char* name, const GridShape& base, std::array<int, 3> patch = {1, 1, 1},
                         const std::vector<Box>& boxes = {}) {
  const auto slice = tov::polytrope_slice(100.0, 2.0, 0.5);
  const tov::TovStar star(*slice, 1.28e-3);
  Errors e[3];
  int levels = 0;
  for (int m = 0; m < 3; ++m) {
    const GridShape s = scaled(base, 1 << m);
    CompositeLayout lay{s, {1, 1, 1}, {}};
    if (!boxes.empty()) {
      std::array<int, 3> pc = patch;
      for (int d = 0; d < s.dimension; ++d) pc[d] *= 1 << m;
      lay = nested_layout(s, pc, boxes);
    }
    levels = lay.finest();
    e[m] = solve_star(star, lay);
  }
  std::printf("TOV metric %-12s levels %d  Linf(psi) %.3e %.3e %.3e order %.2f %.2f | Linf(alpha) %.3e %.3e %.3e order %.2f %.2f | V-cycles %d %d %d\n",
              name, levels, e[0].psi, e[1].psi, e[2].psi, order(e[0].psi, e[1].psi), order(e[1].psi, e[2].psi), e[0].alpha,
              e[1].alpha, e[2].alpha, order(e[0].alpha, e[1].alpha), order(e[1].alpha, e[2].alpha), e[0].cycles,
              e[1].cycles, e[2].cycles);
  if (!boxes.empty()) EXPECT_EQ(levels, static_cast<int>(boxes.size())) << name;
  EXPECT_GT(order(e[1].psi, e[2].psi), 1.7);
  EXPECT_GT(order(e[1].alpha, e[2].alpha), 1.7);
  EXPECT_LT(e[2].psi, 1e-4);
}

GridShape spherical_1d() {
  using B = Boundary;
  return make_shape(CoordinateSystem::spherical, 1, {160, 1, 1}, {0, 0, 0}, {20, 3.141592653589793, 6.283185307179586},
                    {{{B::origin, B::outer}, {B::outer, B::outer}, {B::outer, B::outer}}});
}
GridShape spherical_2d() {
  using B = Boundary;
  return make_shape(CoordinateSystem::spherical, 2, {80, 4, 1}, {0, 0, 0}, {20, 1.5707963267948966, 6.283185307179586},
                    {{{B::origin, B::outer}, {B::axis, B::reflect}, {B::outer, B::outer}}});
}
GridShape cylindrical_2d() {
  using B = Boundary;
  return make_shape(CoordinateSystem::cylindrical, 2, {32, 32, 1}, {0, 0, 0}, {16, 16, 6.283185307179586},
                    {{{B::axis, B::outer}, {B::reflect, B::outer}, {B::outer, B::outer}}});
}
// 3D: phi periodic (the star is the same in every phi; the grid's phi couplings and axis images
// still enter every cell's operator and ghost).
GridShape spherical_3d() {
  using B = Boundary;
  return make_shape(CoordinateSystem::spherical, 3, {80, 4, 4}, {0, 0, 0}, {20, 1.5707963267948966, 6.283185307179586},
                    {{{B::origin, B::outer}, {B::axis, B::reflect}, {B::periodic, B::periodic}}});
}
GridShape cylindrical_3d() {
  using B = Boundary;
  return make_shape(CoordinateSystem::cylindrical, 3, {32, 32, 4}, {0, 0, 0}, {16, 16, 6.283185307179586},
                    {{{B::axis, B::outer}, {B::reflect, B::outer}, {B::periodic, B::periodic}}});
}
Box box(double r0, double r1, double t0, double t1) { return {{{r0, r1}, {t0, t1}, {0, 7}}}; }

}  // namespace

TEST(XCFCTovMetric, Spherical1D) { expect_second_order("spherical 1D", spherical_1d()); }
TEST(XCFCTovMetric, Spherical2D) { expect_second_order("spherical 2D", spherical_2d()); }
TEST(XCFCTovMetric, Cylindrical2D) { expect_second_order("cylindrical 2D", cylindrical_2d()); }
TEST(XCFCTovMetric, Spherical3D) { expect_second_order("spherical 3D", spherical_3d()); }
TEST(XCFCTovMetric, Cylindrical3D) { expect_second_order("cylindrical 3D", cylindrical_3d()); }

// The same stars on refined grids (composite solves): the interfaces cross the star (isotropic
// radius 6.5), where psi and alpha vary most.
TEST(XCFCTovMetric, RefinedSpherical1D) {
  expect_second_order("AMR sph. 1D", spherical_1d(), {8, 1, 1}, {box(0, 8, 0, 4), box(0, 3.5, 0, 4)});
}
TEST(XCFCTovMetric, RefinedSpherical2D) {
  expect_second_order("AMR sph. 2D", spherical_2d(), {8, 2, 1}, {box(0, 8, 0, 2), box(0, 3.5, 0, 2)});
}
TEST(XCFCTovMetric, RefinedCylindrical2D) {
  expect_second_order("AMR cyl. 2D", cylindrical_2d(), {4, 4, 1}, {box(0, 7, 0, 7), box(0, 3.5, 0, 3.5)});
}

TEST(XCFCTovMetric, RefinedCartesian3D) {
  using B = Boundary;
  const GridShape octant = make_shape(CoordinateSystem::cartesian, 3, {8, 8, 8}, {0, 0, 0}, {16, 16, 16},
                                      {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::reflect, B::outer}}});
  const Box level1{{{0, 8}, {0, 8}, {0, 8}}}, level2{{{0, 4}, {0, 4}, {0, 4}}};
  expect_second_order("AMR cart. 3D", octant, {4, 4, 4}, {level1, level2});
}
