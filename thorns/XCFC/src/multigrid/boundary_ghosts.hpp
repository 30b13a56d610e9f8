#pragma once
// Boundary ghosts of a level's ghosted arrays from a scalar equation's boundary conditions: parity
// images across symmetry faces, the axis and the origin; Robin fall-off or Dirichlet values at outer
// faces.
#include <vector>

#include "level.hpp"

namespace remnant::xcfc {

// Fills the face ghosts of a ghosted array (no corners: no stencil uses them). `homogeneous`:
// the conditions of a correction (far value 0, Dirichlet value 0).
void fill_ghosts(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous);

}  // namespace remnant::xcfc
