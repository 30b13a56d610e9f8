#pragma once
// The reference metric f_ij of the coordinates (DESIGN.md section 4). Directions are ordered
// Cartesian (x, y, z), cylindrical (R, z, phi), spherical (r, theta, phi); an axisymmetric 2D grid
// uses the first two and ignores phi, a 1D grid uses the first. All three metrics are diagonal and
// their volume element is separable, sqrt(f) = g_0(x^0) g_1(x^1) g_2(x^2):
//   Cartesian   1 * 1 * 1
//   cylindrical R * 1 * 1
//   spherical   r^2 * sin(theta) * 1
// so that cell volumes and face areas are products of exact 1D integrals (see Block).
// Vector and tensor components are coordinate-basis components throughout.
#include <array>

namespace remnant {

enum class CoordinateSystem { cartesian, cylindrical, spherical };
const char* to_string(CoordinateSystem c);

using Point3 = std::array<double, 3>;
using Matrix3 = std::array<std::array<double, 3>, 3>;
// Christoffel symbols Gamma^a_bc of f, indexed [a][b][c].
using Christoffels = std::array<Matrix3, 3>;

namespace coords {

// True for theta and phi (spherical) and phi (cylindrical): an unused angular direction spans its
// whole range, so that 1D and 2D volumes are those of the full 3D domain.
bool is_angle(CoordinateSystem c, int d);
// g_d(x): the factor of sqrt(f) that depends on direction d.
double volume_factor(CoordinateSystem c, int d, double x);
// The exact integral of g_d over [a, b].
double volume_factor_integral(CoordinateSystem c, int d, double a, double b);
// The g_d-weighted centroid of [a, b], the point that makes linear reconstruction conservative.
// Valid for intervals on either side of an axis (the mirror of the centroid of the mirror cell).
double centroid(CoordinateSystem c, int d, double a, double b);

// Diagonal of f_ij at x.
Point3 metric_diagonal(CoordinateSystem c, const Point3& x);
double sqrt_det_metric(CoordinateSystem c, const Point3& x);
Christoffels christoffels(CoordinateSystem c, const Point3& x);
// The same with the sine and cosine of the polar angle x[1] given (used in spherical coordinates
// only): hot loops compute them once per row of cells instead of once per cell, with the same bits.
Point3 metric_diagonal(CoordinateSystem c, const Point3& x, double sin_theta);
Christoffels christoffels(CoordinateSystem c, const Point3& x, double sin_theta, double cos_theta);

// Cartesian position of the point x (valid for negative R, r, theta too: the extended chart
// whose ghost cells across an axis or the origin the grid fills).
Point3 to_cartesian(CoordinateSystem c, const Point3& x);
// J[A][i] = dX^A / dx^i, Cartesian A, coordinate i.
Matrix3 jacobian(CoordinateSystem c, const Point3& x);
// V^A = J[A][i] v^i; and back (v^i = (J^-1)[i][A] V^A), for vector components.
Point3 vector_to_cartesian(CoordinateSystem c, const Point3& x, const Point3& v);
Point3 vector_from_cartesian(CoordinateSystem c, const Point3& x, const Point3& V);
// Covector components: w_i = J[A][i] W_A.
Point3 covector_from_cartesian(CoordinateSystem c, const Point3& x, const Point3& W);

}  // namespace coords
}  // namespace remnant
