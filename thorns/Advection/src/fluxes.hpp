#pragma once
// Finite-volume pieces of the advection RHS on one block.
#include "exact_solution.hpp"
#include "remnant/grid.hpp"

namespace remnant::advection {

// Upwind flux densities u v^d on every interior face normal to d (faces 0..n), from MC-limited
// linear reconstruction about the cell centroids. `u` needs two ghost layers.
void face_fluxes(const Setup& s, Block& b, const Field& u, const Field& flux, int d);

// rhs = -(1/V) sum_d (F A)_{upper face} - (F A)_{lower face}, over the used directions.
void flux_divergence(Block& b, const Field* flux[3], int dimension, const Field& rhs);

// Largest sum_d |v^d| / dx^d over the block's cells (1/dt at Courant factor 1).
double inverse_dt(const Setup& s, const Block& b, int dimension);

}  // namespace remnant::advection
