#pragma once
// Manufactured solutions for the multigrid tests: u = base + A exp(-sum_c w_c X_c^2) in Cartesian
// components X of the cell position, with its flat Laplacian over the directions the problem has.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "XCFC/multigrid/multigrid.hpp"
#include "XCFC/multigrid/structured_grid.hpp"

namespace remnant::xcfc::test {

struct Bump {
  double base = 1.0, amplitude = 0.3;
  std::array<double, 3> w{0.5, 0.5, 0.5};  // zero: independent of that Cartesian coordinate
  std::array<double, 3> centre{0, 0, 0};
  double operator()(const Point3& X) const {
    double e = 0;
    for (int c = 0; c < 3; ++c) e += w[c] * (X[c] - centre[c]) * (X[c] - centre[c]);
    return base + amplitude * std::exp(-e);
  }
  double laplacian(const Point3& X) const {
    double e = 0, l = 0;
    for (int c = 0; c < 3; ++c) {
      const double y = X[c] - centre[c];
      e += w[c] * y * y;
      l += 4 * w[c] * w[c] * y * y - 2 * w[c];
    }
    return amplitude * std::exp(-e) * l;
  }
  // d/dX_c
  double gradient(const Point3& X, int c) const {
    double e = 0;
    for (int a = 0; a < 3; ++a) e += w[a] * (X[a] - centre[a]) * (X[a] - centre[a]);
    return -2 * w[c] * (X[c] - centre[c]) * amplitude * std::exp(-e);
  }
};

struct Case {
  std::string name;
  GridShape shape;  // n of the coarsest resolution
  Bump bump;
};

inline GridShape scaled(GridShape s, int factor) {
  for (int d = 0; d < s.dimension; ++d) {
    s.dx[d] *= double(s.n[d]) / (s.n[d] * factor);
    s.n[d] *= factor;
  }
  return s;
}

inline GridShape make_shape(CoordinateSystem cs, int dim, std::array<int, 3> n, std::array<double, 3> lo,
                            std::array<double, 3> hi, std::array<std::array<Boundary, 2>, 3> bc) {
  GridShape s;
  s.coordinates = cs;
  s.dimension = dim;
  for (int d = 0; d < 3; ++d) {
    s.n[d] = d < dim ? n[d] : 1;
    s.lo[d] = lo[d];
    s.dx[d] = (hi[d] - lo[d]) / s.n[d];
  }
  s.boundary = bc;
  return s;
}

// The test cases of every coordinate system and dimension the acceptance asks for.
inline std::vector<Case> all_cases() {
  using B = Boundary;
  using C = CoordinateSystem;
  const double pi = 3.141592653589793;
  std::vector<Case> cs;
  const auto outer = B::outer, refl = B::reflect;
  cs.push_back({"cartesian 1D", make_shape(C::cartesian, 1, {32, 1, 1}, {0, 0, 0}, {4, 1, 1}, {{{refl, outer}, {outer, outer}, {outer, outer}}}),
                {1.0, 0.3, {0.6, 0, 0}, {0, 0, 0}}});
  cs.push_back({"cartesian 2D", make_shape(C::cartesian, 2, {32, 16, 1}, {-4, 0, 0}, {4, 4, 1}, {{{outer, outer}, {refl, outer}, {outer, outer}}}),
                {1.0, 0.3, {0.5, 0.7, 0}, {0.3, 0, 0}}});
  cs.push_back({"cartesian 3D", make_shape(C::cartesian, 3, {8, 8, 8}, {0, 0, 0}, {3, 3, 3}, {{{refl, outer}, {refl, outer}, {refl, outer}}}),
                {1.0, 0.3, {0.6, 0.5, 0.7}, {0, 0, 0}}});
  cs.push_back({"cylindrical 2D", make_shape(C::cylindrical, 2, {16, 16, 1}, {0, 0, 0}, {4, 4, 2 * pi}, {{{B::axis, outer}, {refl, outer}, {outer, outer}}}),
                {1.0, 0.3, {0.6, 0.6, 0.4}, {0, 0, 0}}});
  cs.push_back({"spherical 1D", make_shape(C::spherical, 1, {32, 1, 1}, {0, 0, 0}, {5, pi, 2 * pi}, {{{B::origin, outer}, {outer, outer}, {outer, outer}}}),
                {1.0, 0.3, {0.5, 0.5, 0.5}, {0, 0, 0}}});
  cs.push_back({"spherical 2D", make_shape(C::spherical, 2, {16, 8, 1}, {0, 0, 0}, {5, pi / 2, 2 * pi}, {{{B::origin, outer}, {B::axis, refl}, {outer, outer}}}),
                {1.0, 0.3, {0.5, 0.5, 0.8}, {0, 0, 0}}});
  // 3D: phi periodic and turned by pi across the axis and the origin; off-axis bumps (no symmetry
  // about the z axis) so that phi matters.
  cs.push_back({"cylindrical 3D", make_shape(C::cylindrical, 3, {8, 8, 8}, {0, 0, 0}, {4, 4, 2 * pi}, {{{B::axis, outer}, {refl, outer}, {B::periodic, B::periodic}}}),
                {1.0, 0.3, {0.6, 0.5, 0.4}, {0.5, -0.4, 0}}});
  cs.push_back({"spherical 3D", make_shape(C::spherical, 3, {8, 8, 8}, {0, 0, 0}, {5, pi, 2 * pi}, {{{B::origin, outer}, {B::axis, B::axis}, {B::periodic, B::periodic}}}),
                {1.0, 0.3, {0.5, 0.6, 0.7}, {0.4, -0.3, 0.2}}});
  // Cartesian problems of lower dimension do not depend on the unused Cartesian coordinates.
  for (auto& c : cs)
    if (c.shape.coordinates == C::cartesian)
      for (int d = c.shape.dimension; d < 3; ++d) c.bump.w[d] = 0;
  return cs;
}

// Index i fastest over the interior.
template <class F>
void for_cells(const GridShape& s, F&& f) {
  std::size_t q = 0;
  for (int k = 0; k < s.n[2]; ++k)
    for (int j = 0; j < s.n[1]; ++j)
      for (int i = 0; i < s.n[0]; ++i) f(q++, i, j, k);
}

inline double order(double coarse, double fine) { return std::log2(coarse / fine); }

// The scalar xCFC equation whose solution is the bump, with physical signs (s1 = -2 pi E~ <= 0,
// s7 = -A^2/8 <= 0, k >= 0) and s0 making it exact: the psi type Lap u = s1/u + s7/u^7 + s0 or
// the alpha psi type Lap u = k u + s0. Dirichlet values of the bump at the outer faces; the exact
// cell values in *exact when given.
inline ScalarEquation manufactured_equation(const GridShape& s, const Bump& bump, bool nonlinear,
                                            std::vector<double>* exact = nullptr) {
  ScalarEquation eq;
  eq.s0.resize(s.cells());
  if (nonlinear) eq.s1.resize(s.cells()), eq.s7.resize(s.cells());
  else eq.k.resize(s.cells());
  if (exact) exact->resize(s.cells());
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const Point3 X = coords::to_cartesian(s.coordinates, s.point(i, j, k));
    const double u = bump(X), lap = bump.laplacian(X);
    const double w = std::exp(-0.3 * (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));
    if (exact) (*exact)[q] = u;
    if (nonlinear) {
      eq.s1[q] = -0.2 * w, eq.s7[q] = -0.05 * w;
      eq.s0[q] = lap - eq.s1[q] / u - eq.s7[q] / std::pow(u, 7);
    } else {
      eq.k[q] = 0.3 * w;
      eq.s0[q] = lap - eq.k[q] * u;
    }
  });
  eq.dirichlet = [s, bump](const Point3& x) { return bump(coords::to_cartesian(s.coordinates, x)); };
  return eq;
}

}  // namespace remnant::xcfc::test
