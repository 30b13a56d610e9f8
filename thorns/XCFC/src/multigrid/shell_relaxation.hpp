#pragma once
// Plane relaxation of the innermost shells of a 3D spherical level. Next to the origin the angular
// couplings (1 / (r dtheta)^2, 1 / (r sin(theta) dphi)^2) dwarf the radial one, and errors smooth in
// angle are reduced by no line relaxation: each shell's (theta, phi) plane is solved at once instead
// (radial neighbours held). The plane's operator is circulant in phi, so a DFT along phi turns it
// into one tridiagonal system along theta per azimuthal mode; the point term's phi dependence is
// averaged in that preconditioner (it is small beside the angular couplings there).
#include "level.hpp"

namespace remnant::xcfc {

// Shells i = 0 .. shells-1 in turn, one linearised plane correction each; the level's ghosts must
// be current. Returns the number of cells relaxed.
long long relax_inner_shells(Level& L, const ScalarEquation& eq, int shells);

// The innermost shells of a spherical level whose theta coupling exceeds the radial one (the
// shells to relax as planes: i < ~1/dtheta).
int angular_shells(const Level& L);

}  // namespace remnant::xcfc
