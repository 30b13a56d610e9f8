#pragma once
// Geometry-only factors of the xCFC source terms, per part and interior cell, kept between solves:
// the Christoffel symbols of the flat reference metric at each cell's evaluation point, which A^ij
// needs (sin and cos of theta, 1/r per cell and solve otherwise: 16 % of XCFC_VectorPotential in
// 1D, README "Spacetime: XCFC"). Only the
// six symbols that can be non-zero are stored; expand() rebuilds the full array with exact zeros,
// so A^ij takes the same products and sums, bit for bit, as with coords::christoffels.
// Invalidation: built for one mesh (the parts' shapes); current_for() is false once the multigrid
// describes another one (a regrid rebuilds the solver, runtime.cpp: solver(), and XcfcSolver
// rebuilds its geometry when its multigrid was replaced).
#include <vector>

#include "XCFC/multigrid/composite_multigrid.hpp"

namespace remnant::xcfc {

// Gamma^r_thth, Gamma^r_phph, Gamma^th_rth (= Gamma^th_thr), Gamma^th_phph, Gamma^ph_rph
// (= Gamma^ph_phr), Gamma^ph_thph (= Gamma^ph_phth); cylindrical uses r_phph and ph_rph only.
struct CompactChristoffels {
  double r_thth = 0, r_phph = 0, th_rth = 0, th_phph = 0, ph_rph = 0, ph_thph = 0;
};

inline Christoffels expand(const CompactChristoffels& c) {
  Christoffels g{};
  g[0][1][1] = c.r_thth;
  g[0][2][2] = c.r_phph;
  g[1][0][1] = g[1][1][0] = c.th_rth;
  g[1][2][2] = c.th_phph;
  g[2][0][2] = g[2][2][0] = c.ph_rph;
  g[2][1][2] = g[2][2][1] = c.ph_thph;
  return g;
}

class SolverGeometry {
 public:
  SolverGeometry() = default;
  explicit SolverGeometry(const CompositeMultigrid& mg);
  // Whether this was built for mg's parts (same count, shapes and extents).
  bool current_for(const CompositeMultigrid& mg) const;
  int parts() const { return static_cast<int>(christoffels_.size()); }
  // Per interior cell (for_part_cells' q) of part n; empty for a Cartesian part (all symbols zero).
  const std::vector<CompactChristoffels>& christoffels(int n) const { return christoffels_[static_cast<std::size_t>(n)]; }

 private:
  std::vector<GridShape> shapes_;
  std::vector<std::vector<CompactChristoffels>> christoffels_;
};

}  // namespace remnant::xcfc
