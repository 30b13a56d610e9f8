#pragma once
// The magnetic field of the 3D data on the grid's faces (HydroBase::Bface1..3), divergence-free to
// round-off: every face flux is a circulation of a vector potential along the grid's edges
// (HydroBase/vector_potential.hpp), and that potential is built from fluxes of the 3D data's
// densitised field Bt = sqrt(gamma) B (the paper's gauge-independent sqrt(gamma / f) B^j) through
// surfaces of the grid:
// - 2D cylindrical / spherical (averaged over phi): A_phi = Psi / (2 pi) at the grid's nodes, Psi
//   the poloidal flux function: the phi-averaged flux through the z faces from the axis out
//   (cylindrical) or through the r faces from the pole down (spherical). The faces those fluxes
//   cross keep exactly their quadrature (z, resp. r, faces); the others follow from Psi. B^phi is
//   the phi-averaged field averaged over each phi face directly (an unused direction: no
//   divergence).
// - 3D Cartesian: A in the axial gauge A_z = 0 on the grid's edges: A_x and A_y integrated upwards
//   from the grid's lower z face by the fluxes through the x and y faces, A_y on that face from the
//   fluxes through its z faces (x from the grid's lower x face). The x and y faces and the lowest z
//   faces keep their quadrature fluxes; the other z faces follow (the 3D data's own divergence ends
//   there).
// Fluxes are Gauss-Legendre quadratures (3 x 3 points per face) of the interpolated Bt in the
// grid's coordinates; sums run from the grid's lower boundary in a fixed order, so blocks that share
// a face compute the same value. Faces outside the data get zero flux.
#include "HandOff/handoff_state.hpp"
#include "remnant/context.hpp"

namespace remnant::handoff {

// Writes Bface1..3 on the interior faces of every local block (and Bvec from them with the metric's
// psi); throws RunError for targets it cannot fill (a 2D grid without its axis, 3D curvilinear).
void import_magnetic_field(Context& ctx, const HandOffState& st);

// The grid's magnetic energy (1/2) int psi^6 B^2 sqrt(f) d^3x from the faces with psi^4 =
// gamma^(1/3) of the 3D data at the cells (HandOff::source_at_cells) or, with solved_psi, the
// metric's psi; total and toroidal part (B_phi-hat^2). Collective.
struct MagneticEnergy {
  double total = 0, toroidal = 0;
};
MagneticEnergy grid_magnetic_energy(Context& ctx, bool solved_psi);

}  // namespace remnant::handoff
