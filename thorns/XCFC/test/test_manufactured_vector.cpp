// Manufactured solutions of the vector equations. (a) Each Cartesian-component equation (with its
// angular point term and parities) with Dirichlet values: order and V-cycle factor. (b) The whole
// operator Lap X + grad div X / 3 = s through X = B - grad chi / 4 with the Robin far field on a
// domain large enough for the far field not to dominate: order of the error of X.
#include <gtest/gtest.h>

#include "XCFC/vector_poisson.hpp"
#include "manufactured.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;

// V^A = X_A G_A(X) with Gaussians G_A: regular at the origin and axis, axisymmetric and
// equatorially symmetric (x, y: m = 1; z: odd in z).
struct Field {
  Bump g[3];
  // Same profile for x and y (axisymmetry); a spherically symmetric grid needs all three equal.
  Field(const Bump& b, bool spherically_symmetric) {
    for (int a = 0; a < 3; ++a) {
      g[a] = b;
      g[a].base = 0;
      g[a].amplitude = a == 2 && !spherically_symmetric ? 0.8 : 0.5;
    }
  }
  double value(const Point3& X, int a) const { return X[a] * g[a](X); }
  // Flat Laplacian over the active Cartesian directions (w = 0 marks an inactive one).
  double laplacian(const Point3& X, int a) const {
    return X[a] * g[a].laplacian(X) + (g[a].w[a] > 0 ? 2 * g[a].gradient(X, a) : 0.0);
  }
  // d_A d_B V^B by central differences (the operator's grad-div part).
  double grad_div(const Point3& X, int a, const std::array<bool, 3>& active) const {
    const double h = 1e-3;
    auto div = [&](Point3 Y) {
      double d = 0;
      for (int b = 0; b < 3; ++b) {
        if (!active[b]) continue;
        Point3 p = Y, m = Y;
        p[b] += h, m[b] -= h;
        d += (value(p, b) - value(m, b)) / (2 * h);
      }
      return d;
    };
    if (!active[a]) return 0;
    Point3 p = X, m = X;
    p[a] += h, m[a] -= h;
    return (div(p) - div(m)) / (2 * h);
  }
};

std::array<bool, 3> active_directions(const GridShape& s) {
  if (s.coordinates == CoordinateSystem::cartesian) return {s.dimension > 0, s.dimension > 1, s.dimension > 2};
  return {true, true, true};
}

TEST(XCFCVector, CartesianComponentEquations) {
  for (const Case& c : all_cases()) {
    for (int a = 0; a < 3; ++a) {
      if (!cartesian_component_active(c.shape, a)) continue;
      if (c.shape.coordinates == CoordinateSystem::cartesian && a >= c.shape.dimension) continue;
      // Axisymmetric grids: V^y = 0 in the meridional half-plane phi = 0.
      if (c.shape.coordinates != CoordinateSystem::cartesian && c.shape.dimension < 3 && a == 1) continue;
      double err[3];
      SolveStats st[3];
      for (int m = 0; m < 3; ++m) {
        const GridShape s = scaled(c.shape, 1 << m);
        const Field V(c.bump, s.coordinates == CoordinateSystem::spherical && s.dimension == 1);
        Multigrid mg(s);
        ScalarEquation eq = cartesian_component_equation(s, a);
        eq.s0.resize(s.cells());
        std::vector<double> exact(s.cells()), u(s.cells(), 0.0);
        for_cells(s, [&](std::size_t q, int i, int j, int k) {
          const Point3 X = coords::to_cartesian(s.coordinates, s.point(i, j, k));
          exact[q] = V.value(X, a);
          eq.s0[q] = V.laplacian(X, a);
        });
        eq.dirichlet = [&](const Point3& x) { return V.value(coords::to_cartesian(s.coordinates, x), a); };
        SolveSettings set;
        set.tolerance = 1e-10;
        st[m] = mg.solve(eq, u, set);
        err[m] = 0;
        for (std::size_t q = 0; q < u.size(); ++q) err[m] = std::max(err[m], std::abs(u[q] - exact[q]));
      }
      const double p2 = order(err[1], err[2]);
      std::printf("component %c %-15s Linf error %.3e %.3e %.3e  order %.2f %.2f  V-cycles %d %d %d  factor %.3f %.3f %.3f\n",
                  "xyz"[a], c.name.c_str(), err[0], err[1], err[2], order(err[0], err[1]), p2, st[0].cycles,
                  st[1].cycles, st[2].cycles, st[0].factor, st[1].factor, st[2].factor);
      EXPECT_GT(p2, 1.7) << c.name << " component " << a;
      EXPECT_TRUE(st[2].converged) << c.name;
      EXPECT_LT(st[2].factor, 0.35) << c.name;
    }
  }
}

TEST(XCFCVector, FullOperatorWithFarField) {
  for (Case c : all_cases()) {
    // A larger domain: the Robin far field of B and chi is exact only asymptotically.
    for (int d = 0; d < c.shape.dimension; ++d)
      if (!coords::is_angle(c.shape.coordinates, d)) c.shape.dx[d] *= 2.5;
    for (auto& w : c.bump.w) w *= 1.0;
    double err[3];
    int cycles[3];
    for (int m = 0; m < 3; ++m) {
      const GridShape s = scaled(c.shape, 1 << m);
      const Field V(c.bump, s.coordinates == CoordinateSystem::spherical && s.dimension == 1);
      const auto act = active_directions(s);
      CompositeMultigrid mg(s);
      VectorField src_cart, exact_cart;
      for (int a = 0; a < 3; ++a) src_cart[a] = mg.field(), exact_cart[a] = mg.field();
      for_cells(s, [&](std::size_t q, int i, int j, int k) {
        const Point3 X = coords::to_cartesian(s.coordinates, s.point(i, j, k));
        for (int a = 0; a < 3; ++a) {
          if (!act[a]) continue;
          exact_cart[a].part[0][q] = V.value(X, a);
          src_cart[a].part[0][q] = V.laplacian(X, a) + V.grad_div(X, a, act) / 3.0;
        }
      });
      const VectorField src = to_coordinate_components(mg, src_cart);
      VectorPotentials warm;
      VectorField X;
      SolveSettings set;
      set.tolerance = 1e-10;
      const VectorSolveStats st = solve_vector_poisson(mg, src, warm, X, set);
      cycles[m] = st.cycles();
      const VectorField Xc = to_cartesian_components(mg, X);
      err[m] = 0;
      for (int a = 0; a < 3; ++a)
        for (std::size_t q = 0; q < s.cells(); ++q) err[m] = std::max(err[m], std::abs(Xc[a].part[0][q] - exact_cart[a].part[0][q]));
      EXPECT_TRUE(st.converged()) << c.name;
    }
    const double p2 = order(err[1], err[2]);
    std::printf("vector X   %-15s Linf error %.3e %.3e %.3e  order %.2f %.2f  V-cycles (B + chi) %d %d %d\n",
                c.name.c_str(), err[0], err[1], err[2], order(err[0], err[1]), p2, cycles[0], cycles[1], cycles[2]);
    EXPECT_GT(p2, 1.5) << c.name;
  }
}

}  // namespace
