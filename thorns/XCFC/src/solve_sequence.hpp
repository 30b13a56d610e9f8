#pragma once
// One xCFC solve on the Grid's forest in the paper's order: X^i -> A^ij -> psi -> the primitives
// recovered with the new psi -> alpha psi -> beta^i, from the warm starts (cadence.hpp), written to
// Spacetime::metric and XCFC::potentials, logged in xcfc.tsv (solve_log.hpp).
#include "matter_coupling.hpp"
#include "remnant/context.hpp"

namespace remnant::xcfc {

// One solve with the densitised conserved variables held fixed (evolution and the initial
// hand-off); reason: the xcfc.tsv column ("initial", "cadence", "residual").
void solve_sequence(Context& ctx, bool initial, const char* reason);

// XCFC_Initial: the metric of the initial data (XCFC::initial_metric).
void initial_solve(Context& ctx);

// Relative residual of the psi equation with the current matter (A^2 term left out: it is not
// stored between solves, and its contribution is second order in the velocities).
double psi_residual(Context& ctx);

// The primitives recovered with the psi now in Spacetime::metric; throws RunError when a fatal
// error-policy rule fired on any rank.
void recover_with_new_psi(Context& ctx, const MatterGroups& g);

}  // namespace remnant::xcfc
