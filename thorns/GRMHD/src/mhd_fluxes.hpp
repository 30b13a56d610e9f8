#pragma once
// Pass 1 of the MHD right-hand side (mhd_fluxes.cpp).
#include "EOS/eos.hpp"
#include "ct_faces.hpp"
#include "mhd_groups.hpp"
#include "rhs.hpp"

namespace remnant::grmhd {

// HLL fluxes psi^6 F of the hydro components on the interior faces (flux_x/y/z, as compute_block_fluxes)
// and the Riemann data of the edge EMFs (into `ct`, ct_faces.hpp) on the interior faces and one
// ghost layer of faces in each used transverse direction. Reads prim, metric and Bvec everywhere,
// Bface_d. Only what `emfs`' EMFs read is computed (MhdSweepOutputs); the rest is left as it was.
void compute_block_fluxes_mhd(const eos::EOS& eos, const RhsSettings& s, const Groups& g, const MhdGroups& mg,
                              const CtFaces& ct, Block& b, EmfScheme emfs = EmfScheme::arithmetic);

// What the sweep computes besides the interior faces' hydro fluxes, speeds and transport velocities.
// arithmetic and uct_contact: everything. uct_hll: on the ghost-layer faces only the speeds and
// transport velocities (ct components kAlphaPlus .. kVtRight; no HLL solve there), and the induction
// fluxes (kFluxNext, kFluxPrev) only where an edge has an unused transverse direction (1D, 2D).
struct MhdSweepOutputs {
  bool ghost_line_fluxes = true;
  bool induction_fluxes = true;
  static MhdSweepOutputs for_emfs(EmfScheme emfs, const Block& b);
};

}  // namespace remnant::grmhd
