#pragma once
// Positivity-preserving limiter of the rest-mass fluxes (GRMHD::positivity_limiter), after Hu, Adams
// & Shu 2013 (J. Comput. Phys. 242, 169) and Wu & Tang 2015 for RMHD: each face's high-order HLL
// flux of D (and of D Ye, with the same weight) is blended with a first-order local Lax-Friedrichs
// flux, F = theta F_high + (1 - theta) F_low, theta per face as large as keeps D >= epsilon after
// the forward-Euler step u + dt L(u) of which every SSP Runge-Kutta stage is a convex combination.
//
// Why per face: the update of cell i, D_i - dt/V sum_faces (+-A F), is the mean over its 2N faces
// (N used directions) of D_i -+ 2N dt (A/V) F_face, so D_i^new >= epsilon if every such term is.
// Each term involves one face and one of its two cells only: theta of a face is the smaller of
// its two cells' bounds, computed identically by both blocks that hold the face (ghost cells from
// the synchronised primitives), which keeps the scheme conservative.
//
// The Lax-Friedrichs flux of cell-centred states, 0.5 (D_m vt_m + D_p vt_p) - 0.5 a (D_p - D_m)
// with a = max(|vt_m|, |vt_p|) (vt = alpha v - beta, the transport velocity of D), makes every term
// non-negative when 2N a dt A/V <= 1, i.e. for MoL::cfl <= 1/(2N) (0.25 in 2D): where even the low
// order term falls below epsilon, theta = 0 (the first-order flux) is the best the limiter can do.
// With theta = 1 (nothing to limit) the flux keeps its bits: a run the limiter never touches is
// bit-identical to one without it.
#include <algorithm>

#include "groups.hpp"
#include "remnant/context.hpp"
#include "remnant/grid.hpp"

namespace remnant::grmhd {

// The largest theta in [0, 1] with cell - c (f_low + theta (f_high - f_low)) >= floor, for the
// term of one face in the update of one cell: c = 2N dt A/V times +1 for the cell's upper face
// (the flux leaves it) or -1 for its lower face. 0 where the low-order term itself is below floor.
inline double positivity_theta_one_cell(double cell, double c, double f_high, double f_low, double floor) {
  const double high = cell - c * f_high;
  if (high >= floor) return 1.0;
  const double low = cell - c * f_low;
  if (!(low > floor)) return 0.0;
  return std::clamp((low - floor) / (low - high), 0.0, 1.0);
}

// theta of the face between cell m (below) and cell p (above) with D_m, D_p, their factors
// c = 2N dt A/V (>= 0) and the two fluxes; the floor of a cell is min(epsilon, its own D).
inline double positivity_theta(double d_m, double d_p, double c_m, double c_p, double f_high, double f_low,
                               double epsilon) {
  const double tm = positivity_theta_one_cell(d_m, c_m, f_high, f_low, std::min(epsilon, d_m));
  const double tp = positivity_theta_one_cell(d_p, -c_p, f_high, f_low, std::min(epsilon, d_p));
  return std::min(tm, tp);
}

// The local Lax-Friedrichs flux of a conserved density q transported with vt (cells m, p).
inline double lax_friedrichs_flux(double q_m, double q_p, double vt_m, double vt_p, double a) {
  return 0.5 * (q_m * vt_m + q_p * vt_p) - 0.5 * a * (q_p - q_m);
}

// Limits the D and D Ye components of flux_x/y/z on the interior faces of block b (before the
// Grid's flux correction) for a forward-Euler step dt. D of a cell is psi^6 rho W from the
// primitives (interior and ghosts). Returns the number of faces with theta < 1.
long limit_block_mass_fluxes(const Groups& g, double dt, double epsilon, Block& b);

// Paramcheck: a warning where MoL::cfl exceeds 1/(2 x dimension), the limiter's guarantee.
void check_positivity_limiter(Context& ctx);

// GRMHD::positivity_limiter on every local block for the step ctx.dt() (nothing with none).
void apply_positivity_limiter(Context& ctx, const Groups& g);

}  // namespace remnant::grmhd
