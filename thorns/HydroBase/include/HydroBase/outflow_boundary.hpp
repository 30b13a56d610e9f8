#pragma once
// HydroBase::outflow_boundary: what the fluid's primitive ghosts hold at the domain's `outflow`
// faces. zero_gradient: the Grid's copy of the outermost interior layer (matter may flow in where
// the flow there points inward). no_inflow ("diode"): after that copy, the normal velocity
// component of a ghost cell is set to zero where it points into the domain, and W is made
// consistent with the remaining velocity; ghosts whose flow leaves the domain stay untouched.
#include "remnant/context.hpp"
#include "remnant/grid.hpp"

namespace remnant::hydrobase {

// The prim components the condition needs: the vector's component along each coordinate
// direction (from the group's tensor declaration) and W.
struct PrimVelocity {
  int vel[3] = {-1, -1, -1};
  int lorentz = -1;
};

// No inflow on one face (direction d, upper or lower side) of one block: ghost layers of `prim`
// in direction d over the full extent of the other directions. Only the ghosts are changed.
void no_inflow_face(Block& b, int prim, const PrimVelocity& c, int d, bool upper);

// HydroBase_OutflowBoundary: registers the condition for HydroBase::prim with the grid.
void register_outflow_boundary(Context& ctx);

}  // namespace remnant::hydrobase
