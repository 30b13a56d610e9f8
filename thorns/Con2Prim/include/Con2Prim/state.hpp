#pragma once
// Conserved and primitive variables at one point.
//
// Conserved variables are NOT densitised: D = rho W, S_i = (rho h W^2 + B^2) v_i - (B.v) B_i,
// tau = rho h W^2 - p + B^2 (1 + v^2)/2 - (B.v)^2/2 - D, DYe = D Ye, with B^i the Eulerian field
// (Heaviside-Lorentz with sqrt(4 pi) absorbed: b^2 = B^2/W^2 + (B.v)^2). The GRMHD thorn stores
// sqrt(gamma/f)-densitised variables: it divides D, S_i, tau, DYe (and B^i) by sqrt(gamma/f)
// before calling con2prim and multiplies the recomputed conserved variables back.
#include "Con2Prim/metric.hpp"

namespace remnant::con2prim {

struct Conserved {
  double D = 0;
  Vec3 S{};  // S_i (covariant)
  double tau = 0;
  Vec3 B{};  // B^i (contravariant)
  double DYe = 0;
};

struct Primitives {
  double rho = 0;
  Vec3 v{};  // v^i (contravariant), Eulerian 3-velocity
  double W = 1;
  double eps = 0, press = 0, T = 0, ye = 0, cs2 = 0;
  Vec3 B{};  // B^i, carried unchanged by the recovery
};

}  // namespace remnant::con2prim
