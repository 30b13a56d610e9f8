#pragma once
// Between solves (XCFC::update_every): the A^ij of an update, from the last two solves' X.
#include "XCFC/xcfc_system.hpp"
#include "grid_bridge.hpp"
#include "remnant/context.hpp"

namespace remnant::xcfc {

// st.A and st.A2 at the current time: A^ij is linear in X^i, and X^i is extrapolated linearly in
// time from the last two solves, so A^ij is too (A2 = A_ij A^ij from it). The A^ij of the two
// solves' potentials (XCFC::potentials, XCFC::potentials_before) are computed once per solve
// interval and kept in the runtime.
void load_update_A(Context& ctx, const GridBridge& br, XcfcSolver& sv, XcfcState& st);

}  // namespace remnant::xcfc
