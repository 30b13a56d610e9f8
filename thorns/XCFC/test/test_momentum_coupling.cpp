// The momentum coupling of the xCFC system (issue 20, item 3) against closed-form solutions.
// Manufactured problem through the real source assembly (XcfcSolver: X^i -> A^ij -> psi -> alpha psi
// -> beta^i): closed-form Cartesian fields X, psi, alpha psi and beta with toroidal (rotation) and
// poloidal parts; the sources E~, S~_j, S~ that make them exact are built from the paper's
// equations written out in Cartesian components (analytic_fields.hpp), so every coupling constant
// (8 pi of X, 2 pi and 1/8 of psi, 2 pi, 2 S~ and 7/8 of alpha psi, 16 pi and 2 A^ij d_j(alpha
// psi^-6) of beta) is checked against an independent statement of the equations. The X and beta
// equations get their own S~_j (two calls of the solver), so that beta has a closed form while
// alpha psi^-6 varies. Second-order convergence of every field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "XCFC/xcfc_system.hpp"
#include "analytic_fields.hpp"
#include "manufactured.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;
constexpr double pi = std::numbers::pi;

struct ChainCase {
  const char* name;
  GridShape shape;        // coarsest
  bool spherical;         // a 1D spherical grid: radial fields only, spherically symmetric scalars
  bool toroidal;          // the grid allows a rotation-like (toroidal) part
};

// exp(-a varpi^2 - b z^2); spherically symmetric when a == b.
double gauss(const Point3& X, double a, double b) { return std::exp(-a * (X[0] * X[0] + X[1] * X[1]) - b * X[2] * X[2]); }

struct Fields {
  VectorFn X, beta;
  ScalarFn psi, alpha_psi;
};

Fields fields(const ChainCase& c) {
  // Gaussian widths (varpi, z): equal where the grid needs spherical symmetry.
  const double zx = c.spherical ? 0.5 : 0.6, zb = c.spherical ? 0.35 : 0.45, zp = c.spherical ? 0.4 : 0.5,
               za = c.spherical ? 0.3 : 0.35;
  const double ax = c.spherical ? 0.4 : 0.3, ab = c.spherical ? -0.2 : 0.25;  // z amplitudes (poloidal)
  const double tx = c.toroidal ? 0.3 : 0.0, tb = c.toroidal ? 0.25 : 0.0;     // toroidal amplitudes
  Fields f;
  f.X = [=](const Point3& X) {
    const double gp = 0.4 * gauss(X, 0.5, zx), gz = ax * gauss(X, 0.5, zx), gt = tx * gauss(X, 0.4, 0.5);
    return Point3{X[0] * gp - X[1] * gt, X[1] * gp + X[0] * gt, X[2] * gz};
  };
  f.beta = [=](const Point3& X) {
    const double hp = -0.2 * gauss(X, 0.35, zb), hz = ab * gauss(X, 0.35, zb), ht = tb * gauss(X, 0.3, 0.4);
    return Point3{X[0] * hp - X[1] * ht, X[1] * hp + X[0] * ht, X[2] * hz};
  };
  f.psi = [=](const Point3& X) { return 1 + 0.3 * gauss(X, 0.4, zp); };
  f.alpha_psi = [=](const Point3& X) { return 1 - 0.25 * gauss(X, 0.3, za); };
  return f;
}

struct ChainErrors {
  double X = 0, psi = 0, alpha_psi = 0, beta = 0;
};

ChainErrors solve_chain(const ChainCase& c, const GridShape& s) {
  const Fields F = fields(c);
  XcfcSolver solver(s);
  CompositeMultigrid& mg = solver.multigrid();
  CompositeField E = mg.field(), Str = mg.field();
  VectorField S_X, S_beta;
  for (int a = 0; a < 3; ++a) S_X[a] = mg.field(), S_beta[a] = mg.field();
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const Point3 x = s.point(i, j, k), X = coords::to_cartesian(s.coordinates, x);
    const auto A = conformal_killing(F.X, X);
    const double A2 = square(A), psi = F.psi(X), ap = F.alpha_psi(X);
    // Lap psi = -2 pi E~ / psi - A2 / (8 psi^7)
    const double e = -(laplacian(F.psi, X) + A2 / (8 * std::pow(psi, 7))) * psi / (2 * pi);
    // Lap(alpha psi) = alpha psi [2 pi psi^-2 (E~ + 2 S~) + (7/8) psi^-8 A2]
    const double str = (laplacian(F.alpha_psi, X) / ap - 0.875 * A2 / std::pow(psi, 8)) * psi * psi / (4 * pi) - e / 2;
    // Delta_L X = 8 pi S~ ;  Delta_L beta = 16 pi w S~ + 2 A^ij d_j w,  w = alpha psi^-6
    const ScalarFn w = [&](const Point3& Y) { return F.alpha_psi(Y) / std::pow(F.psi(Y), 7); };
    const Point3 LX = vector_laplacian(F.X, X), Lb = vector_laplacian(F.beta, X);
    Point3 sx, sb, dw;
    for (int b = 0; b < 3; ++b) dw[b] = d1(w, X, b);
    for (int a = 0; a < 3; ++a) {
      sx[a] = LX[a] / (8 * pi);
      double adw = 0;
      for (int b = 0; b < 3; ++b) adw += A[a][b] * dw[b];
      sb[a] = (Lb[a] - 2 * adw) / (16 * pi * w(X));
    }
    const Point3 sx_dn = coords::covector_from_cartesian(s.coordinates, x, sx);
    const Point3 sb_dn = coords::covector_from_cartesian(s.coordinates, x, sb);
    E.part[0][q] = e;
    Str.part[0][q] = str;
    for (int a = 0; a < 3; ++a) S_X[a].part[0][q] = sx_dn[a], S_beta[a].part[0][q] = sb_dn[a];
  });
  XcfcState st;
  XcfcStats stats;
  SolveSettings set;
  set.tolerance = 1e-11;
  set.full_multigrid = true;
  solver.solve_conformal_factor(E, S_X, st, stats, set);
  solver.solve_lapse_and_shift(E, S_beta, Str, st, stats, set);
  EXPECT_TRUE(stats.X.converged() && stats.psi.converged && stats.alpha_psi.converged && stats.beta.converged())
      << c.name;
  ChainErrors err;
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const Point3 x = s.point(i, j, k), X = coords::to_cartesian(s.coordinates, x);
    Point3 xu, bu;
    for (int a = 0; a < 3; ++a) xu[a] = st.X[a].part[0][q], bu[a] = st.beta[a].part[0][q];
    const Point3 Xn = coords::vector_to_cartesian(s.coordinates, x, xu), bn = coords::vector_to_cartesian(s.coordinates, x, bu);
    const Point3 Xe = F.X(X), be = F.beta(X);
    for (int a = 0; a < 3; ++a) {
      err.X = std::max(err.X, std::abs(Xn[a] - Xe[a]));
      err.beta = std::max(err.beta, std::abs(bn[a] - be[a]));
    }
    err.psi = std::max(err.psi, std::abs(st.psi.part[0][q] - F.psi(X)));
    err.alpha_psi = std::max(err.alpha_psi, std::abs(st.alpha_psi.part[0][q] - F.alpha_psi(X)));
  });
  return err;
}

// min_order: the order between the two finest grids (the coarse 3D Cartesian grid, 8 cells across
// the fields, is not yet in the asymptotic range: 1.62 there, 1.84-2.15 on the others). Every field
// must also be within 1e-2 of its closed form on the finest grid (measured 3e-4 to 6e-3; the
// fields are of size 0.1-0.4, so a wrong coupling constant misses by far more).
void expect_chain_second_order(const ChainCase& c, double min_order = 1.8) {
  ChainErrors e[3];
  for (int m = 0; m < 3; ++m) e[m] = solve_chain(c, scaled(c.shape, 1 << m));
  auto line = [&](const char* what, double ChainErrors::*f) {
    std::printf("xCFC chain %-15s %-9s Linf %.3e %.3e %.3e  order %.2f %.2f\n", c.name, what, e[0].*f, e[1].*f,
                e[2].*f, order(e[0].*f, e[1].*f), order(e[1].*f, e[2].*f));
    EXPECT_GT(order(e[1].*f, e[2].*f), min_order) << c.name << " " << what;
    EXPECT_LT(e[2].*f, 1e-2) << c.name << " " << what;
  };
  line("X", &ChainErrors::X);
  line("psi", &ChainErrors::psi);
  line("alpha psi", &ChainErrors::alpha_psi);
  line("beta", &ChainErrors::beta);
}

using B = Boundary;
using C = CoordinateSystem;

}  // namespace

TEST(XCFCMomentumCoupling, ManufacturedChainSpherical1D) {
  expect_chain_second_order({"spherical 1D",
                             make_shape(C::spherical, 1, {24, 1, 1}, {0, 0, 0}, {12, pi, 2 * pi},
                                        {{{B::origin, B::outer}, {B::outer, B::outer}, {B::outer, B::outer}}}),
                             true, false});
}
TEST(XCFCMomentumCoupling, ManufacturedChainSpherical2D) {
  expect_chain_second_order({"spherical 2D",
                             make_shape(C::spherical, 2, {24, 8, 1}, {0, 0, 0}, {12, pi / 2, 2 * pi},
                                        {{{B::origin, B::outer}, {B::axis, B::reflect}, {B::outer, B::outer}}}),
                             false, true});
}
TEST(XCFCMomentumCoupling, ManufacturedChainCylindrical2D) {
  expect_chain_second_order({"cylindrical 2D",
                             make_shape(C::cylindrical, 2, {16, 16, 1}, {0, 0, 0}, {10, 10, 2 * pi},
                                        {{{B::axis, B::outer}, {B::reflect, B::outer}, {B::outer, B::outer}}}),
                             false, true});
}
TEST(XCFCMomentumCoupling, ManufacturedChainCartesian3D) {
  expect_chain_second_order({"cartesian 3D",
                             make_shape(C::cartesian, 3, {8, 8, 8}, {0, 0, 0}, {8, 8, 8},
                                        {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::reflect, B::outer}}}),
                             false, false},
                            1.5);
}
