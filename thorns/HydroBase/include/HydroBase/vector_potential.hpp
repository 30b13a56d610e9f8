#pragma once
// Divergence-free face fields from a vector potential, for any initial-data thorn (issue 15).
//
// The face value of HydroBase::Bface<d> is psi^6 B^d averaged over the face with the weight sqrt(f),
// so that area * value is the magnetic flux through the face (docs: /work/notes/mhd.md). By Stokes,
// that flux is the circulation of the covariant potential A_k around the face:
//   flux(face) = sum over its four edges of +- integral A_k dx^k,
// independently of the metric (psi^6 sqrt(f) B^i = epsilon^{ijk} d_j A_k with the orientation of
// the Cartesian frame). Each edge integral is computed once (Gauss-Legendre along the edge) and
// shared by the faces around it, so the fluxes out of every cell sum to zero to round-off.
//
// Conventions (the Block's, remnant/grid.hpp):
// - Directions are (x, y, z), (R, z, phi), (r, theta, phi). (R, z, phi) is a left-handed order,
//   so cylindrical circulations take a minus sign: the same A gives the same physical B in every
//   coordinate system (A_phi = B0 varpi^2 / 2 is the uniform field B0 along +z everywhere).
// - An unused direction (1D/2D) stores one face/edge index. The potential must not depend on that
//   coordinate. A line integral along an unused angle runs over its whole range (2 pi for phi,
//   matching the face areas of an axisymmetric grid); along an unused non-angular direction it is
//   A at the cell centre times 1 (the unit weight the Block gives that direction).
// - Edges of zero length (along phi on an axis, along theta and phi at the origin) integrate to 0;
//   edges along an axis (z at R = 0, r at theta = 0, pi) are evaluated at phi = 0 so that every
//   block sees one value. Faces of zero area get the value 0.
// - Only interior faces and edges are written (block-boundary faces included: both blocks compute
//   them from bit-identical edge coordinates, hence identical values).
#include <array>
#include <functional>
#include <vector>

#include "remnant/coordinates.hpp"
#include "remnant/grid.hpp"

namespace remnant::hydrobase {

// Covariant components (A_0, A_1, A_2) at a point given in the block's coordinates.
using CovariantPotential = std::function<std::array<double, 3>(const Point3& x)>;
// An axisymmetric potential: the covariant A_phi (= x A_y - y A_x) as a function of the coordinate
// cylindrical radius varpi >= 0 and z. Regular fields have A_phi = O(varpi^2) near the axis.
using AxisymmetricPotential = std::function<double(double varpi, double z)>;

// A_phi(varpi, z) as covariant components in coordinates c (Cartesian: A_x = -y A_phi / varpi^2,
// A_y = x A_phi / varpi^2, 0 on the axis).
CovariantPotential covariant_from_axisymmetric(CoordinateSystem c, AxisymmetricPotential a_phi);
// The same for A_phi given as a function of the point in the block's coordinates (e.g. a law of
// the local pressure interpolated from the grid).
CovariantPotential covariant_from_phi_component(CoordinateSystem c, std::function<double(const Point3& x)> a_phi);

// Line integrals of A along the interior edges of one block. Edges along a are indexed by the cell
// in direction a and the face (0..n, or 0 where unused) in the other two.
class EdgeIntegrals {
 public:
  EdgeIntegrals(const Block& b, const CovariantPotential& A, int quadrature_points = 4);
  double operator()(int a, int i, int j, int k) const {
    const auto& e = extent_[static_cast<std::size_t>(a)];
    return value_[static_cast<std::size_t>(a)][static_cast<std::size_t>(i + e[0] * (j + e[1] * k))];
  }
  // Signed circulation around the lower face of cell (i, j, k) normal to d: the flux through it.
  double face_flux(int d, int i, int j, int k) const;

 private:
  std::array<std::vector<double>, 3> value_;
  std::array<std::array<int, 3>, 3> extent_{};
  std::array<bool, 3> used_{};
  double orientation_ = 1.0;
};

// Writes flux / area on every interior face of the block (faces[d] normal to d; face index 0..n
// in used directions, 0 in unused ones).
void set_faces_from_edges(const Block& b, const EdgeIntegrals& edges, const std::array<Field, 3>& faces);
inline void set_faces_from_potential(const Block& b, const CovariantPotential& A, const std::array<Field, 3>& faces,
                                     int quadrature_points = 4) {
  set_faces_from_edges(b, EdgeIntegrals(b, A, quadrature_points), faces);
}

// The discrete divergence (1/V) sum over the cell's faces of +- area * value (used directions
// only), and optionally sum |area * value| / V, the scale against which it is round-off.
double cell_divergence(const Block& b, const std::array<Field, 3>& faces, int i, int j, int k,
                       double* magnitude = nullptr);

// psi^6 B at the centre of cell (i, j, k) in the orthonormal frame of f: per direction the mean of
// the two faces' averages of sqrt(f_dd) psi^6 B^d (flux / the face's integral of sqrt(f / f_dd)),
// so that |B| = psi^2 |result| / psi^6. Unlike the area-weighted coordinate mean of Bvec
// (HydroBase/magnetic_field.hpp) it stays accurate next to the origin and the axis, where
// coordinate components such as B^theta ~ 1/r vary fastest (for a uniform field on 16^2 spherical
// cells the area-weighted mean is 12 % off |B| there, this 2 %).
Point3 cell_orthonormal_densitised_field(const Block& b, const std::array<Field, 3>& faces, int i, int j, int k);
// The integral of sqrt(f / f_dd) over the lower face of cell (i, j, k) normal to d.
double face_orthonormal_area(const Block& b, int d, int i, int j, int k);

// Gauss-Legendre nodes on [-1, 1] and weights, n = 1..16.
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights);
// Integral of A(x)[k] dx^k along coordinate k from lo to hi, the other coordinates of x held, by
// the Gauss-Legendre rule (nodes, weights) on [-1, 1].
double gauss_line_integral(const CovariantPotential& A, Point3 x, int k, double lo, double hi,
                           const std::vector<double>& nodes, const std::vector<double>& weights);

}  // namespace remnant::hydrobase
