#pragma once
// Rest-mass bookkeeping (HydroBase::mass_budget, both components densitised like D and integrated by
// MoL with the same Runge-Kutta weights as D):
//   outflow: d/dt = the part of -dD/dt that comes from faces on the domain boundary, i.e. the rest
//            mass that has left through the outer boundary (negative: entered);
//   source:  the change of D made by the atmosphere and the error policy in the con2prim sweeps.
// Summed with the cell volumes, rest mass + outflow - source is constant to round-off.
#include <array>
#include <cstdint>

#include "groups.hpp"

namespace remnant::grmhd {

using Budget = vars::HydroBase::mass_budget;

// Cells per direction of the whole domain at level 0 (Grid::ncells) and the used directions.
struct DomainCells {
  std::array<std::int64_t, 3> n{1, 1, 1};
  int dimension = 3;
  static DomainCells of(const Context& ctx);
  // Whether the lower / upper face of block b in direction d lies on the domain boundary.
  bool lower(const Block& b, int d) const { return d < dimension && b.index[d] == 0; }
  bool upper(const Block& b, int d) const {
    return d < dimension && (b.index[d] + 1) * b.n[d] == (n[d] << b.level);
  }
};

// mass_budget_rhs of one block from its D fluxes (after compute_block_fluxes).
void outflow_rhs_block(const Groups& g, const DomainCells& dom, Block& b);

}  // namespace remnant::grmhd
