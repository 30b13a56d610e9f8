#pragma once
// Zebra line relaxation on 3D cylindrical and spherical levels, where the coupling across phi
// (1 / (varpi dphi)^2) dominates next to the axis and the angular couplings next to the origin, so
// that point smoothing stalls. Lines along direction d are coloured by the parity of their two
// transverse indices (a line's transverse neighbours have the other colour); each line is one
// tridiagonal solve (one Newton linearisation for nonlinear equations), cyclic along a periodic phi.
#include "level.hpp"

namespace remnant::xcfc {

// One colour of lines along d; the level's ghosts must be current (they are held, except that the
// line's own ends follow it: Robin, Dirichlet, reflection onto the end cell, periodic wrap).
// Returns the number of cells relaxed.
long long line_pass_3d(Level& L, const ScalarEquation& eq, int d, int colour);

// Linear equations (no s1, s7): the Thomas factors of every line, kept on the level for the
// passes of one solve (sets L.factored; nonlinear equations are linearised per pass instead).
void factor_lines_3d(Level& L, const ScalarEquation& eq);

}  // namespace remnant::xcfc
