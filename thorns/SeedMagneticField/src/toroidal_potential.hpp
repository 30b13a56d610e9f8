#pragma once
// A toroidal field on a 3D grid as the curl of A = A_z(varpi, z) e_z (Cartesian components), so that
// div B = 0 to round-off like any potential field: psi^6 sqrt(f) B^phi-coordinate = -(1/varpi) dA_z/dvarpi,
// i.e. A_z(varpi, z) = -integral_0^varpi varpi' q(varpi', z) dvarpi' with q = psi^6 B^phi (the
// densitised coordinate component). q is a grid function: it is binned on a (varpi, z) table
// (volume-weighted means of the cells in each bin, over all ranks), integrated along varpi, and A_z
// interpolated bilinearly. The resulting B^phi is q smoothed over one bin (spacing: the grid's
// finest non-angular cell width).
#include <functional>
#include <vector>

#include "HydroBase/vector_potential.hpp"
#include "remnant/grid.hpp"

namespace remnant::seed {

class ToroidalPotentialTable {
 public:
  // q(block, i, j, k) at interior cells. Collective over the grid's ranks.
  ToroidalPotentialTable(GridDriver& grid, const std::function<double(Block&, int, int, int)>& q);
  double a_z(double varpi, double z) const;
  // Covariant components of A in the coordinates c (all coordinate systems).
  hydrobase::CovariantPotential potential(CoordinateSystem c) const;
  double spacing() const { return h_; }

 private:
  double h_ = 1.0, z0_ = 0.0;
  int nw_ = 1, nz_ = 1;
  std::vector<double> a_;  // A_z at varpi = m h (m = 0..nw), rows at z = z0 + (l + 1/2) h
};

}  // namespace remnant::seed
