#pragma once
// One xCFC solve on the Grid's forest as scheduled steps in the paper's order (thorn.yaml):
// X^i and A^ij -> psi -> [group XCFC_RecoverPrimitives: the matter thorn recovers the primitives
// with the new psi] -> alpha psi -> beta^i, from the warm starts (cadence.hpp), written to
// Spacetime::metric and XCFC::potentials, logged in xcfc.tsv (solve_log.hpp). The initial metric
// takes the same steps in the group XCFC_Initial.
#include "remnant/context.hpp"

namespace remnant::xcfc {

// Evolution steps, each a no-op unless the stage is `solve` (XCFC_Cadence sets it).
void step_vector_potential(Context& ctx);  // warm start, X^i, A^ij
void step_conformal_factor(Context& ctx);  // psi, then the recovery is due
void step_lapse(Context& ctx);             // alpha psi with the recovered matter
void step_shift(Context& ctx);             // beta^i; stores and records the solve

// Initial metric (XCFC::initial_metric): from_conserved takes X, A, psi here and the lapse and
// shift after the recovery; from_primitives iterates psi with the primitives fixed (no recovery).
void initial_conformal_factor(Context& ctx);
void initial_psi_iteration(Context& ctx);  // from_primitives: one psi solve per pass
void initial_lapse_and_shift(Context& ctx);

// Relative residual of the psi equation with the current matter (A^2 term left out: it is not
// stored between solves, and its contribution is second order in the velocities).
double psi_residual(Context& ctx);

}  // namespace remnant::xcfc
