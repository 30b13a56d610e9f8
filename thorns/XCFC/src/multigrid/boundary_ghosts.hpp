#pragma once
// Boundary ghosts of a level's ghosted arrays from a scalar equation's boundary conditions: parity
// images across symmetry faces, the axis and the origin; Robin fall-off or Dirichlet values at outer
// faces.
#include <array>
#include <vector>

#include "level.hpp"

namespace remnant::xcfc {

// A box of cell indices [b[d], e[d]) per direction: the part of a level whose ghosts a rank's
// stencils read (its slab or line split and their neighbours). Faces outside it are not filled.
struct GhostBox {
  std::array<int, 3> b{-1, -1, -1}, e{1 << 30, 1 << 30, 1 << 30};
};

// Fills the face ghosts of a ghosted array (no corners: no stencil uses them). `homogeneous`:
// the conditions of a correction (far value 0, Dirichlet value 0). Only the ghosts next to the
// box's cells (a ghost's value depends on its own face entry only, so the filled ones have the
// bits of a whole fill).
// `base`: the ghosted offset of a's first entry (kLevelBase: the level's own window, L.gbase; 0 for
// an array of the whole level). Returns the number of ghosts filled.
inline constexpr std::ptrdiff_t kLevelBase = -1;
std::size_t fill_ghosts(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous,
                        const GhostBox& box = GhostBox{}, std::ptrdiff_t base = kLevelBase);

}  // namespace remnant::xcfc
