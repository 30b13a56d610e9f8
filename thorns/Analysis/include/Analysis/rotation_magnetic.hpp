#pragma once
// The magnetic terms of the rotation diagnostics (Analysis::rotation with evolved B), computed by
// Analysis_RotationMagnetic and folded into Analysis_Star's row:
//   M_komar += int alpha psi^6 S_EM dV,  S_EM = (E^2 + B^2) / 2 = [B^2 (1 - v^2) + (B.v)^2] / 2
//              (the Maxwell stress's trace with the ideal-MHD E = -v x B; cons.tau already holds
//              the field's energy, and S~_i v^i its Poynting part, so only this trace is missing);
//   |W| = M_proper + T + E_mag - M_komar (E_mag: the magnetic diagnostics' energy), T_over_W = T / |W|.
// B^2 = psi^4 f_ij B^i B^j etc. from HydroBase::Bvec and prim.vel at the cell centres.
#include "Analysis/magnetic_diagnostics.hpp"
#include "Analysis/rotation_diagnostics.hpp"
#include "remnant/context.hpp"

namespace remnant::analysis {

// int alpha psi^6 S_EM dV over the grid (collective; the same bits on any rank count).
double magnetic_komar_stress(Context& ctx);

// M_komar and T_over_W of `rotation` with the field's stress (komar_stress) and energy (E_mag).
void add_magnetic_terms(RotationDiagnostics& rotation, double komar_stress, double E_mag);

}  // namespace remnant::analysis
