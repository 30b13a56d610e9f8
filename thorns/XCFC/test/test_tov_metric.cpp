// The metric of a TOV star from the xCFC solver given the star's matter (densitised E~ = psi^6 E as
// a hand-off would import it, S~ = 3 psi^6 p with the solver's psi) against the exact isotropic TOV
// solution (thorns/TOV): second-order convergence of psi and alpha, 1D and 2D spherical.
#include <gtest/gtest.h>

#include <cmath>

#include "TOV/tov_solver.hpp"
#include "XCFC/xcfc_system.hpp"
#include "manufactured.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;

struct Errors {
  double psi, alpha;
  int cycles;
};

Errors solve_star(const tov::TovStar& star, GridShape s) {
  XcfcSolver solver(s);
  std::vector<double> E(s.cells()), p(s.cells()), psi_exact(s.cells()), alpha_exact(s.cells());
  VectorField S;
  for (auto& c : S) c.assign(s.cells(), 0.0);
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const Point3 X = coords::to_cartesian(s.coordinates, s.point(i, j, k));
    const tov::TovPoint t = star.at(std::hypot(X[0], X[1], X[2]));
    E[q] = std::pow(t.psi, 6) * t.rho * (1 + t.eps);
    p[q] = t.press;
    psi_exact[q] = t.psi;
    alpha_exact[q] = t.alpha;
  });
  XcfcState st;
  XcfcStats stats;
  SolveSettings set;
  set.tolerance = 1e-11;
  set.full_multigrid = true;
  solver.solve_conformal_factor(E, S, st, stats, set);
  std::vector<double> Str(s.cells());
  for (std::size_t q = 0; q < Str.size(); ++q) Str[q] = 3 * std::pow(st.psi[q], 6) * p[q];
  solver.solve_lapse_and_shift(E, S, Str, st, stats, set);
  const std::vector<double> alpha = st.alpha();
  Errors e{0, 0, stats.psi.cycles + stats.alpha_psi.cycles};
  for (std::size_t q = 0; q < Str.size(); ++q) {
    e.psi = std::max(e.psi, std::abs(st.psi[q] - psi_exact[q]));
    e.alpha = std::max(e.alpha, std::abs(alpha[q] - alpha_exact[q]));
  }
  EXPECT_TRUE(stats.psi.converged && stats.alpha_psi.converged);
  return e;
}

void expect_second_order(const char* name, const GridShape& base) {
  const auto slice = tov::polytrope_slice(100.0, 2.0, 0.5);
  const tov::TovStar star(*slice, 1.28e-3);
  Errors e[3];
  for (int m = 0; m < 3; ++m) e[m] = solve_star(star, scaled(base, 1 << m));
  std::printf("TOV metric %-12s Linf(psi) %.3e %.3e %.3e order %.2f %.2f | Linf(alpha) %.3e %.3e %.3e order %.2f %.2f | V-cycles %d %d %d\n",
              name, e[0].psi, e[1].psi, e[2].psi, order(e[0].psi, e[1].psi), order(e[1].psi, e[2].psi), e[0].alpha,
              e[1].alpha, e[2].alpha, order(e[0].alpha, e[1].alpha), order(e[1].alpha, e[2].alpha), e[0].cycles,
              e[1].cycles, e[2].cycles);
  EXPECT_GT(order(e[1].psi, e[2].psi), 1.7);
  EXPECT_GT(order(e[1].alpha, e[2].alpha), 1.7);
  EXPECT_LT(e[2].psi, 1e-4);
}

}  // namespace

TEST(XCFCTovMetric, Spherical1D) {
  using B = Boundary;
  expect_second_order("spherical 1D", make_shape(CoordinateSystem::spherical, 1, {160, 1, 1}, {0, 0, 0}, {20, 3.141592653589793, 6.283185307179586},
                                                 {{{B::origin, B::outer}, {B::outer, B::outer}, {B::outer, B::outer}}}));
}

TEST(XCFCTovMetric, Spherical2D) {
  using B = Boundary;
  expect_second_order("spherical 2D", make_shape(CoordinateSystem::spherical, 2, {80, 4, 1}, {0, 0, 0}, {20, 1.5707963267948966, 6.283185307179586},
                                                 {{{B::origin, B::outer}, {B::axis, B::reflect}, {B::outer, B::outer}}}));
}

TEST(XCFCTovMetric, Cylindrical2D) {
  using B = Boundary;
  expect_second_order("cylindrical 2D", make_shape(CoordinateSystem::cylindrical, 2, {32, 32, 1}, {0, 0, 0}, {16, 16, 6.283185307179586},
                                                   {{{B::axis, B::outer}, {B::reflect, B::outer}, {B::outer, B::outer}}}));
}
