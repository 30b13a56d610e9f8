#pragma once
// Metric derivatives at a cell's centroid, for the gravity sources. The metric is held at the cell
// centres (XCFC solves there); the fluid's cell values, and the pressure balance of the flux
// divergence (alpha psi^6 p times the exact cell average of d ln sqrt f), belong to the
// sqrt(f)-weighted centroid, which next to an axis lies far from the centre (2 dR / 3 against dR / 2
// in the first cylindrical cell). The centred difference is the centre's derivative: in that first
// cylindrical cell it was 25 % short of
// the pressure gradient it balances, an O(dR) outward force that set a static star's axis flowing
// (issue 15). Here: the derivative at the centroid x_c of the parabola through the centres i-1, i, i+1,
//   f'(x_c) = (f(i+1) - f(i-1)) / 2h + w (f(i+1) - 2 f(i) + f(i-1)),   w = (x_c - x_i) / h^2,
// exact for quadratics. Applied along cylindrical R and spherical theta; w = 0 elsewhere, which keeps
// the bits of the Cartesian, z and phi directions and of spherical r: at a spherical origin (centroid
// 3 dr / 4) the correction made the magnetised DRNS's residual flow in the origin cell 1.4x larger
// (MagnetisedDrns.EquilibriumFieldKeepsTheStarAtRest), so that cell's balance is left as it was (open).
#include <array>
#include <cstddef>
#include <vector>

#include "remnant/grid.hpp"

namespace remnant::grmhd {

class CentroidOffsets {
 public:
  // used[d]: the block's used directions.
  CentroidOffsets(const Block& b, const std::array<bool, 3>& used) {
    const CoordinateSystem cs = b.coordinates;
    for (int d = 0; d < 3; ++d) {
      std::vector<double>& w = w_[static_cast<std::size_t>(d)];
      w.assign(static_cast<std::size_t>(b.n[d]), 0.0);
      const bool curved = (cs == CoordinateSystem::cylindrical && d == 0) || (cs == CoordinateSystem::spherical && d == 1);
      if (!curved || !used[d]) continue;
      const double inv_h2 = 1.0 / (b.dx[d] * b.dx[d]);
      for (int i = 0; i < b.n[d]; ++i) w[static_cast<std::size_t>(i)] = (b.centroid(d, i) - b.x(d, i)) * inv_h2;
    }
  }
  double weight(int d, int i) const { return w_[static_cast<std::size_t>(d)][static_cast<std::size_t>(i)]; }

 private:
  std::array<std::vector<double>, 3> w_;
};

}  // namespace remnant::grmhd
