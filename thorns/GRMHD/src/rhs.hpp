#pragma once
// The GRMHD right-hand side of one block in two passes, so that the Grid can correct the face
// fluxes at refinement boundaries in between (refluxing).
#include "GRMHD/reconstruction.hpp"
#include "EOS/eos.hpp"
#include "groups.hpp"
#include "line_scratch.hpp"
#include "well_balanced.hpp"

namespace remnant::grmhd {

struct RhsSettings {
  Reconstruction reconstruction = Reconstruction::ppm;
  MetricFaceInterpolation metric_faces = MetricFaceInterpolation::linear;
  // GRMHD::well_balanced = isentropic (well_balanced.hpp; ideal gas only, checked at start-up).
  bool well_balanced = false;
};

// Pass 1: the HLL flux densities psi^6 F^d on every interior face, into flux_x/y/z (per unit face
// area, as GridDriver::correct_fluxes expects).
void compute_block_fluxes(const eos::EOS& eos, const RhsSettings& s, const Groups& g, Block& b);
// Pass 2: cons_rhs = -(flux divergence with exact face areas and volumes) + psi^6 sources.
// wb.on: the static pressure sources of the momentum replaced as well_balanced.hpp says (the fluxes
// must then come from compute_block_fluxes with RhsSettings::well_balanced).
void compute_block_rhs(const Groups& g, Block& b, const WellBalancedSources& wb = {});
// Pass 2 with the magnetised stress tensor in the sources (cell-centred B^i in group `bvec`).
void compute_block_rhs_mhd(const Groups& g, int bvec, Block& b, const WellBalancedSources& wb = {});
// The same cell by cell, without the vectorised rows that 3D Cartesian blocks take (the tests
// compare the two bit for bit).
void compute_block_rhs_per_cell(const Groups& g, Block& b);
void compute_block_rhs_mhd_per_cell(const Groups& g, int bvec, Block& b);

}  // namespace remnant::grmhd
