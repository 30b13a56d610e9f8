#pragma once
// Diagnostics of a collision (HeadOn runs; Analysis::collision_diagnostics): the global masses from
// the metric and matter, the l = 2, m = 0 quadrupole moment of the rest mass about the z axis and its
// first time derivative from the momentum density (Dimmelmeier, Font & Mueller 2002, A&A 388, 917,
// "first moment of momentum density": no second time derivative of the density is taken), and the
// positions of the density maxima on either side of z = 0.
//
// With rho* = D~ (the densitised conserved density) and S~_i (densitised momentum), flat volume:
//   I = int rho* (z^2 - (x^2 + y^2) / 2) d^3x = int rho* r^2 P2(cos theta) d^3x,
//   dI/dt = int S~_i xi^i d^3x,  xi = grad(z^2 - (x^2 + y^2)/2) = (-x, -y, 2z)  (continuity),
//   h+ = sin^2(theta_obs) / D * d^2I/dt^2 = sin^2(theta_obs) A20 / (8 D) sqrt(15 / pi),
// i.e. A20 = 8 sqrt(pi / 15) d/dt (dI/dt), Dimmelmeier et al.'s A^E2_20 (their eq. with
// 32 pi^(3/2) / sqrt(15) and theta over [0, pi/2] is the same integral with equatorial symmetry).
// Masses: M_adm = int psi^-1 E~ d^3x (the xCFC ADM mass, -1/(2 pi) times the flux of grad psi, with the
// A_ij A^ij term left out: it vanishes for matter at rest and is second order in the velocities);
// M_komar = int [alpha (E~ + S~) - 2 beta^i S~_i] d^3x. Every integral is over the whole space: the
// grid's integral times 2 per reflecting symmetry plane through 0 (an octant: 8).
#include <cstdint>
#include <string>

#include "remnant/context.hpp"

namespace remnant::analysis {

struct CollisionDiagnostics {
  double M_rest = 0, M_adm = 0, M_komar = 0;  // whole space
  double quad_I = 0, quad_dI = 0;             // I and dI/dt (whole space)
  double z_max_upper = 0, z_max_lower = 0;    // z of the density maxima in z > 0 and z <= 0 (mirror if absent)
  double rho_max_upper = 0;                   // the density maximum in z > 0
  double rho_max_point = 0;  // point value of rho at its maximum (include/Analysis/point_maximum.hpp; NaN on spherical grids)
};

// True when the columns are written: Analysis::collision_diagnostics = always, or auto with HeadOn active.
bool collision_diagnostics_enabled(const Context& ctx);
// The factor 2^(number of reflecting planes through 0) that takes the grid's integrals to whole space.
double symmetry_factor(const Context& ctx);
// Collective; the same bits on every rank and for any rank count (per-block sums added in block order).
CollisionDiagnostics collision_diagnostics(Context& ctx);
// The point value of rho at the cell of its largest cell average (src/point_maximum_grid.cpp); collective,
// the same on every rank count.
double rho_max_point(Context& ctx);

}  // namespace remnant::analysis
