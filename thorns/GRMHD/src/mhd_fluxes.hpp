#pragma once
// Pass 1 of the MHD right-hand side (mhd_fluxes.cpp).
#include "EOS/eos.hpp"
#include "mhd_groups.hpp"
#include "rhs.hpp"

namespace remnant::grmhd {

// HLL fluxes psi^6 F of the hydro components on the interior faces (flux_x/y/z, as compute_block_fluxes)
// and the Riemann data of the edge EMFs (ct_x/y/z) on the interior faces and one ghost layer of
// faces in each used transverse direction. Reads prim, metric and Bvec everywhere, Bface_d.
// The ghost-layer faces get what `emfs`' EMFs read there: with uct_hll only the speeds and transport
// velocities (ct components kAlphaPlus .. kVtRight; flux_x/y/z and the induction fluxes there are
// left as they were, which saves their HLL solves), with arithmetic and uct_contact everything.
void compute_block_fluxes_mhd(const eos::EOS& eos, const RhsSettings& s, const Groups& g, const MhdGroups& mg,
                              Block& b, EmfScheme emfs = EmfScheme::arithmetic);

}  // namespace remnant::grmhd
