#pragma once
// Closed-form Cartesian fields and their derivatives by fourth-order central differences of the
// closed forms (truncation ~1e-9, far below the solver's discretisation errors), for manufactured
// problems of the whole xCFC system: the xCFC operators written out in Cartesian components,
// independently of the solver's coordinate-basis finite volumes.
#include <array>
#include <cmath>
#include <functional>

#include "remnant/coordinates.hpp"

namespace remnant::xcfc::test {

using ScalarFn = std::function<double(const Point3&)>;
using VectorFn = std::function<Point3(const Point3&)>;

// d/dX_a of f, fourth order.
inline double d1(const ScalarFn& f, const Point3& X, int a, double h = 1e-2) {
  auto at = [&](double s) {
    Point3 Y = X;
    Y[a] += s * h;
    return f(Y);
  };
  return (at(-2) - 8 * at(-1) + 8 * at(1) - at(2)) / (12 * h);
}
// d^2/dX_a dX_b of f, fourth order.
inline double d2(const ScalarFn& f, const Point3& X, int a, int b, double h = 1e-2) {
  if (a == b) {
    auto at = [&](double s) {
      Point3 Y = X;
      Y[a] += s * h;
      return f(Y);
    };
    return (-at(-2) + 16 * at(-1) - 30 * at(0) + 16 * at(1) - at(2)) / (12 * h * h);
  }
  return d1([&](const Point3& Y) { return d1(f, Y, b, h); }, X, a, h);
}
inline ScalarFn component(const VectorFn& V, int c) {
  return [V, c](const Point3& X) { return V(X)[c]; };
}
inline double laplacian(const ScalarFn& f, const Point3& X) { return d2(f, X, 0, 0) + d2(f, X, 1, 1) + d2(f, X, 2, 2); }
// (Delta_L V)^a = Lap V^a + (1/3) d_a d_b V^b
inline Point3 vector_laplacian(const VectorFn& V, const Point3& X) {
  Point3 r{};
  for (int a = 0; a < 3; ++a) {
    r[a] = laplacian(component(V, a), X);
    for (int b = 0; b < 3; ++b) r[a] += d2(component(V, b), X, a, b) / 3.0;
  }
  return r;
}
// A^ab = d_a V^b + d_b V^a - (2/3) delta^ab d_c V^c (flat Cartesian metric).
inline std::array<Point3, 3> conformal_killing(const VectorFn& V, const Point3& X) {
  double D[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) D[a][b] = d1(component(V, b), X, a);
  const double div = D[0][0] + D[1][1] + D[2][2];
  std::array<Point3, 3> A{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) A[a][b] = D[a][b] + D[b][a] - (a == b ? 2.0 / 3.0 * div : 0.0);
  return A;
}
inline double square(const std::array<Point3, 3>& A) {
  double s = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) s += A[a][b] * A[a][b];
  return s;
}

}  // namespace remnant::xcfc::test
