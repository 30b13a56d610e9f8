// Reference metrics of the three coordinate systems: volume factors, their exact integrals and
// centroids, Christoffel symbols and the map to Cartesian coordinates.
#include "remnant/coordinates.hpp"

#include <cmath>

namespace remnant {

const char* to_string(CoordinateSystem c) {
  switch (c) {
    case CoordinateSystem::cartesian: return "cartesian";
    case CoordinateSystem::cylindrical: return "cylindrical";
    case CoordinateSystem::spherical: return "spherical";
  }
  return "?";
}

namespace coords {

bool is_angle(CoordinateSystem c, int d) {
  return (c == CoordinateSystem::spherical && d >= 1) || (c == CoordinateSystem::cylindrical && d == 2);
}

double volume_factor(CoordinateSystem c, int d, double x) {
  if (c == CoordinateSystem::cylindrical && d == 0) return x;
  if (c == CoordinateSystem::spherical && d == 0) return x * x;
  if (c == CoordinateSystem::spherical && d == 1) return std::sin(x);
  return 1.0;
}

double volume_factor_integral(CoordinateSystem c, int d, double a, double b) {
  const double h = b - a;
  if (c == CoordinateSystem::cylindrical && d == 0) return 0.5 * h * (a + b);
  if (c == CoordinateSystem::spherical && d == 0) return h * (a * a + a * b + b * b) / 3.0;
  // cos a - cos b without cancellation for narrow cells.
  if (c == CoordinateSystem::spherical && d == 1) return 2.0 * std::sin(0.5 * (a + b)) * std::sin(0.5 * h);
  return h;
}

namespace {
// 1 - h cot h, accurate for small h (series) and large h.
double one_minus_h_cot_h(double h) {
  if (std::abs(h) < 1e-2) {
    const double h2 = h * h;
    return h2 / 3.0 + h2 * h2 / 45.0 + 2.0 * h2 * h2 * h2 / 945.0;
  }
  return 1.0 - h / std::tan(h);
}
}  // namespace

double centroid(CoordinateSystem c, int d, double a, double b) {
  const double m = 0.5 * (a + b);
  if (c == CoordinateSystem::cylindrical && d == 0) return (2.0 / 3.0) * (a * a + a * b + b * b) / (a + b);
  if (c == CoordinateSystem::spherical && d == 0)
    return 0.75 * (a + b) * (a * a + b * b) / (a * a + a * b + b * b);
  if (c == CoordinateSystem::spherical && d == 1) {
    // m + cot(m) (1 - h cot h) with h the half width: no cancellation for narrow cells.
    const double s = std::sin(m);
    if (s == 0.0) return m;
    return m + std::cos(m) / s * one_minus_h_cot_h(0.5 * (b - a));
  }
  return m;
}

Point3 metric_diagonal(CoordinateSystem c, const Point3& x, double s) {
  switch (c) {
    case CoordinateSystem::cartesian: return {1, 1, 1};
    case CoordinateSystem::cylindrical: return {1, 1, x[0] * x[0]};
    case CoordinateSystem::spherical: return {1, x[0] * x[0], x[0] * x[0] * s * s};
  }
  return {1, 1, 1};
}

Point3 metric_diagonal(CoordinateSystem c, const Point3& x) {
  return metric_diagonal(c, x, c == CoordinateSystem::spherical ? std::sin(x[1]) : 0.0);
}

double sqrt_det_metric(CoordinateSystem c, const Point3& x) {
  return volume_factor(c, 0, x[0]) * volume_factor(c, 1, x[1]) * volume_factor(c, 2, x[2]);
}

Christoffels christoffels(CoordinateSystem c, const Point3& x) {
  const bool sph = c == CoordinateSystem::spherical;
  return christoffels(c, x, sph ? std::sin(x[1]) : 0.0, sph ? std::cos(x[1]) : 0.0);
}

Christoffels christoffels(CoordinateSystem c, const Point3& x, double s, double co) {
  Christoffels g{};
  if (c == CoordinateSystem::cylindrical) {
    const double R = x[0];
    g[0][2][2] = -R;                            // Gamma^R_phiphi
    g[2][0][2] = g[2][2][0] = 1.0 / R;          // Gamma^phi_Rphi
  } else if (c == CoordinateSystem::spherical) {
    const double r = x[0];
    g[0][1][1] = -r;                            // Gamma^r_thth
    g[0][2][2] = -r * s * s;                    // Gamma^r_phph
    g[1][0][1] = g[1][1][0] = 1.0 / r;          // Gamma^th_rth
    g[1][2][2] = -s * co;                       // Gamma^th_phph
    g[2][0][2] = g[2][2][0] = 1.0 / r;          // Gamma^ph_rph
    g[2][1][2] = g[2][2][1] = co / s;           // Gamma^ph_thph
  }
  return g;
}

Point3 to_cartesian(CoordinateSystem c, const Point3& x) {
  switch (c) {
    case CoordinateSystem::cartesian: return x;
    case CoordinateSystem::cylindrical: return {x[0] * std::cos(x[2]), x[0] * std::sin(x[2]), x[1]};
    case CoordinateSystem::spherical: {
      const double s = std::sin(x[1]);
      return {x[0] * s * std::cos(x[2]), x[0] * s * std::sin(x[2]), x[0] * std::cos(x[1])};
    }
  }
  return x;
}

Matrix3 jacobian(CoordinateSystem c, const Point3& x) {
  Matrix3 J{};
  switch (c) {
    case CoordinateSystem::cartesian:
      J[0][0] = J[1][1] = J[2][2] = 1;
      break;
    case CoordinateSystem::cylindrical: {
      const double R = x[0], cp = std::cos(x[2]), sp = std::sin(x[2]);
      J[0] = {cp, 0, -R * sp};
      J[1] = {sp, 0, R * cp};
      J[2] = {0, 1, 0};
      break;
    }
    case CoordinateSystem::spherical: {
      const double r = x[0], st = std::sin(x[1]), ct = std::cos(x[1]), cp = std::cos(x[2]), sp = std::sin(x[2]);
      J[0] = {st * cp, r * ct * cp, -r * st * sp};
      J[1] = {st * sp, r * ct * sp, r * st * cp};
      J[2] = {ct, -r * st, 0};
      break;
    }
  }
  return J;
}

Point3 vector_to_cartesian(CoordinateSystem c, const Point3& x, const Point3& v) {
  const Matrix3 J = jacobian(c, x);
  Point3 V{};
  for (int A = 0; A < 3; ++A)
    for (int i = 0; i < 3; ++i) V[A] += J[A][i] * v[i];
  return V;
}

Point3 vector_from_cartesian(CoordinateSystem c, const Point3& x, const Point3& V) {
  // The metric is diagonal: (J^-1)[i][A] = J[A][i] / f_ii.
  const Matrix3 J = jacobian(c, x);
  const Point3 f = metric_diagonal(c, x);
  Point3 v{};
  for (int i = 0; i < 3; ++i) {
    for (int A = 0; A < 3; ++A) v[i] += J[A][i] * V[A];
    v[i] /= f[i];
  }
  return v;
}

Point3 covector_from_cartesian(CoordinateSystem c, const Point3& x, const Point3& W) {
  const Matrix3 J = jacobian(c, x);
  Point3 w{};
  for (int i = 0; i < 3; ++i)
    for (int A = 0; A < 3; ++A) w[i] += J[A][i] * W[A];
  return w;
}

}  // namespace coords
}  // namespace remnant
