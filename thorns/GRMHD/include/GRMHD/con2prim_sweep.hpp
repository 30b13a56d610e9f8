#pragma once
// Primitive recovery and atmosphere over the interior of a block (after every MoL substep), and the
// conserved variables from primitives (initial data). Both undo / apply the psi^6 densitisation.
#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/report.hpp"
#include "Con2Prim/settings.hpp"
#include "EOS/eos.hpp"
#include <string>

#include "GRMHD/grid_access.hpp"

namespace remnant::grmhd {

// cons -> prim with the paper's recovery; cons is overwritten with the conserved variables of the
// corrected primitives (atmosphere, policy).
// The first cell in which a fatal rule fired, if any, is described in `fatal_cell`.
void recover_block(const eos::EOS& eos, const con2prim::Settings& s, const atmosphere::Atmosphere& atm,
                   const Groups& g, Block& b, con2prim::Diagnostics& diag, std::string& fatal_cell);

// Initial data: the primitives (rho, v, eps, Ye) are made consistent (atmosphere, error policy with
// eps trusted, T from eps, p and cs2 from the EOS) and the conserved variables computed.
void prim_to_cons_block(const eos::EOS& eos, const con2prim::Settings& s, const atmosphere::Atmosphere& atm,
                        const Groups& g, Block& b, con2prim::Diagnostics& diag);

}  // namespace remnant::grmhd
