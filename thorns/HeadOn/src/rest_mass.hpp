#pragma once
#include "remnant/context.hpp"

namespace remnant::headon {
// HeadOn_FixRestMass (in XCFC's from_primitives psi passes): rho = lambda rho_iso in the stars, with
// lambda = int psi_iso^6 rho_iso dV / int psi^6 W rho_iso dV (psi the current one), eps and p from the
// cold slice, then the primitives completed and the conserved variables computed (HydroBase).
void fix_rest_mass(Context& ctx);
}  // namespace remnant::headon
