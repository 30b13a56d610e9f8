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
// - 3D (Cartesian, cylindrical, spherical): A in an axial gauge (A_z = 0, resp. A_r = 0) from the
//   fluxes through the grid's faces, summed from the grid's lower faces (potential_edges.hpp); on
//   refined grids the levels' edges are matched (coarse = sum of the fine ones).
// Fluxes are Gauss-Legendre quadratures (3 x 3 points per face) of the interpolated Bt in the
// grid's coordinates; sums run from the grid's lower boundary in a fixed order, so blocks that share
// a face compute the same value. Faces outside the data get zero flux.
#include "HandOff/handoff_state.hpp"
#include "remnant/context.hpp"

namespace remnant::handoff {

// Writes Bface1..3 on the interior faces of every local block (and Bvec from them with the metric's
// psi); throws RunError for targets it cannot fill (a 2D grid without its axis).
void import_magnetic_field(Context& ctx, const HandOffState& st);

// The grid's magnetic energy (1/2) int psi^6 B^2 sqrt(f) d^3x from the faces with psi^4 =
// gamma^(1/3) of the 3D data at the cells (HandOff::source_at_cells) or, with solved_psi, the
// metric's psi; total and toroidal part (B_phi-hat^2). Collective.
struct MagneticEnergy {
  double total = 0, toroidal = 0;
};
MagneticEnergy grid_magnetic_energy(Context& ctx, bool solved_psi);

}  // namespace remnant::handoff
