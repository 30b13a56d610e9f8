#pragma once
// Magnetic diagnostics (issue 15), computed by Analysis_Magnetic when HydroBase::magnetic_field is
// evolved and written as extra analysis.tsv columns (see README.md for the definitions):
//   divB_max   max over cells of |div B| h / max |B| over the cell and its face neighbours,
//              div B the discrete divergence of the face fluxes, h the cell's smallest width;
//   E_mag      (1/2) integral of B^2 psi^6 sqrt(f) d^3x (B^2 = gamma_ij B^i B^j, Eulerian field);
//   E_mag_pol, E_mag_tor  the same with the poloidal (R, z) and toroidal (phi) parts of B^2;
//   B_max      max over cells of sqrt(gamma_ij B^i B^j), in Gauss.
#include <array>
#include <cstdint>

#include "remnant/context.hpp"
#include "remnant/grid.hpp"

namespace remnant::analysis {

struct MagneticDiagnostics {
  std::int64_t iteration = -1;
  double divB_max = 0, E_mag = 0, E_mag_pol = 0, E_mag_tor = 0, B_max_gauss = 0;
};

// One block: writes the energy densities (per unit coordinate volume: (1/2) psi^6 B^2 and its
// poloidal and toroidal parts) at interior cells into `densities` and returns the block's maxima.
// The face fields need valid ghosts (the neighbourhood of divB_max).
// The neighbourhood scale of divB_max is floored at `scale_floor` (the coordinator passes
// kDivBScaleFloor times the grid's largest |psi^6 B|): where the field is far weaker than its
// maximum, e.g. behind a field loop that moved on, the divergence is the round-off of the field
// that was there, and is measured against that field's size, not against the weak remainder.
inline constexpr double kDivBScaleFloor = 0.1;
struct MagneticBlockMaxima {
  double div_scaled = 0;  // max |div| h / max(neighbourhood max |B|, scale_floor)
  double B = 0;           // max sqrt(gamma_ij B^i B^j), code units
};
MagneticBlockMaxima magnetic_block_pass(const Block& b, const std::array<Field, 3>& faces, Field psi,
                                        const std::array<Field, 3>& densities, double scale_floor = 0);
// max over the block's interior cells of |psi^6 B| (flat orthonormal norm): the scale of the floor.
double densitised_field_max(const Block& b, const std::array<Field, 3>& faces);

// Collective over the grid's ranks.
MagneticDiagnostics magnetic_diagnostics(Context& ctx);

// True when the run evolves B (HydroBase::magnetic_field == evolved): analysis.tsv gets the columns.
bool magnetic_run(const Context& ctx);

}  // namespace remnant::analysis
