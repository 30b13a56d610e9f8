#pragma once
// The uniform grid the elliptic solver works on: the Grid's finest uniform level as one logically
// rectangular array (every rank holds all of it; see README.md, "MPI"). Cell-centred, i fastest;
// interior arrays have n0*n1*n2 entries. Unused directions have one cell.
#include <array>
#include <cstddef>
#include <cstdint>

#include "remnant/coordinates.hpp"
#include "remnant/domain.hpp"

namespace remnant::xcfc {

// The face kinds of the shared domain model (remnant/domain.hpp). Boundary::outer (= outflow) is
// the far field: Robin (1/r^p fall-off) or Dirichlet values; reflect, axis, origin take the field's
// parity; periodic is phi of a 3D cylindrical or spherical grid (the full 2 pi); interface is a
// refined patch's face inside the domain, whose ghosts are filled by the composite solver
// (neighbour patches, coarse-fine interpolation) and held by the smoothers.
using remnant::Boundary;

struct GridShape {
  CoordinateSystem coordinates = CoordinateSystem::cartesian;
  int dimension = 3;
  std::array<int, 3> n{1, 1, 1};
  std::array<double, 3> lo{0, 0, 0};   // lower face coordinates
  std::array<double, 3> dx{1, 1, 1};   // cell widths (used directions)
  std::array<std::array<Boundary, 2>, 3> boundary{};  // [direction][lower, upper]

  bool used(int d) const { return d < dimension; }
  std::size_t cells() const { return static_cast<std::size_t>(n[0]) * n[1] * n[2]; }
  double centre(int d, int i) const { return lo[d] + (i + 0.5) * dx[d]; }
  double face(int d, int i) const { return lo[d] + i * dx[d]; }
  // Where a cell's tensors are evaluated: unused theta is the equator, unused phi (2D axisymmetry)
  // the meridional half-plane phi = 0.
  Point3 point(int i, int j, int k) const;
  // The faces as the shared domain model sees them (ghost images, parities).
  DomainFaces faces() const { return {coordinates, dimension, boundary}; }
  std::array<std::int64_t, 3> cell_counts() const { return {n[0], n[1], n[2]}; }
  // Point reflection through the spherical origin maps theta to pi - theta unless the domain ends
  // at the equator with a reflection (then the mirror cell has the same theta index).
  bool origin_flips_theta() const { return faces().origin_flips_theta(); }
  // The cell whose value (times the field's parity at that face) the ghost I beyond the face
  // (d, side) takes: the mirror cell across a symmetry face, with theta flipped through the origin
  // and, on 3D grids, phi turned by pi across the axis or the origin; periodic faces wrap. I may lie
  // beyond other faces too (those coordinates are kept). (DomainFaces::cell_image, with theta over
  // [0, pi] where the origin flips it.)
  std::array<long long, 3> image(std::array<long long, 3> I, int d, int side) const {
    return faces().cell_image(I, d, side, cell_counts());
  }
  // Whether phi is turned by pi across an axis or the origin (3D curvilinear grids): their phi
  // levels must keep an even cell count.
  bool turns_phi() const { return faces().turns_phi(); }
};

// Parity of a field at each symmetry face: +1 even, -1 odd. Outer faces ignore it.
using Parities = std::array<std::array<double, 2>, 3>;
inline constexpr Parities kEven{{{1, 1}, {1, 1}, {1, 1}}};

}  // namespace remnant::xcfc
