#pragma once
// The magnetic field of GRMHD's shock-tube initial data (HydroBase::magnetic_field = evolved): the
// coordinate components B^i of the left and right states (GRMHD::shock_field_left/right; a jump of
// B^1 would not be divergence-free and is refused), plus, for tests in any coordinate system, the
// field of a smooth covariant vector potential of amplitude GRMHD::field_potential_amplitude:
//   Cartesian:   A = A0 (sin 2pi y sin 2pi z, sin 2pi z sin 2pi x, sin 2pi x sin 2pi y)
//   cylindrical: A = A0 (0, R sin phi, R^2 cos 2pi z)               (R, z, phi; A_z = A0 y: a uniform B^x)
//   spherical:   A = A0 (r^2 cos theta, 0, r^2 sin^2 theta cos 2pi r)   (r, theta, phi)
// (smooth through the axis and the origin). Face values are circulations of A around the face (edge
// integrals by 8-point Gauss-Legendre, so that fine edges sum to the coarse edge to round-off) over the exact face area, so the discrete divergence of every cell
// is zero to round-off whatever the quadrature. Flat space: psi = 1 is assumed (psi^6 B = B).
#include <array>
#include <functional>

#include "remnant/context.hpp"
#include "remnant/grid.hpp"

namespace remnant::grmhd {

using CovariantPotential = std::function<std::array<double, 3>(const Point3&)>;

// The test potential above for a coordinate system.
CovariantPotential test_potential(CoordinateSystem cs, double amplitude);
// The potential of a uniform field B^z = b along the Cartesian z axis (GRMHD::field_potential =
// uniform_z): A = b (-y, x, 0)/2, A_phi = b R^2/2 (cylindrical), A_phi = b r^2 sin^2 theta/2 (spherical).
CovariantPotential uniform_z_potential(CoordinateSystem cs, double b);
// A uniform field B^x = b (uniform_x): A_z = b y in every coordinate system's components.
CovariantPotential uniform_x_potential(CoordinateSystem cs, double b);

// Adds to Bface1..3 (groups bface) of the interior faces the face fluxes / area of potential A; with
// ghost_layers > 0 also to that many layers of ghost faces in the used directions.
void add_potential_field(const CovariantPotential& A, const std::array<int, 3>& bface, Block& b, int ghost_layers = 0);

// The shock tube's face fields (GRMHD_InitialField): the uniform left/right fields plus the potential's.
void shock_tube_field(Context& ctx);

}  // namespace remnant::grmhd
