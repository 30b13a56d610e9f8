#include "XCFC/solver_geometry.hpp"

#include <stdexcept>

namespace remnant::xcfc {
namespace {

bool same_shape(const GridShape& a, const GridShape& b) {
  return a.coordinates == b.coordinates && a.dimension == b.dimension && a.n == b.n && a.lo == b.lo && a.dx == b.dx;
}

CompactChristoffels compact(const Christoffels& g) {
  CompactChristoffels c;
  c.r_thth = g[0][1][1], c.r_phph = g[0][2][2], c.th_rth = g[1][0][1], c.th_phph = g[1][2][2];
  c.ph_rph = g[2][0][2], c.ph_thph = g[2][1][2];
  // The compact form must be exact: expand() has to give back every symbol.
  if (expand(c) != g) throw std::logic_error("XCFC: a Christoffel symbol outside the compact set is non-zero");
  return c;
}

}  // namespace

SolverGeometry::SolverGeometry(const CompositeMultigrid& mg) {
  for (int n = 0; n < mg.parts(); ++n) {
    const PartGeometry& pg = mg.part(n);
    const GridShape& s = pg.shape;
    shapes_.push_back(s);
    // Cartesian parts: every symbol is zero; none stored (48 bytes per cell otherwise).
    std::vector<CompactChristoffels>& cells =
        christoffels_.emplace_back(s.coordinates == CoordinateSystem::cartesian ? 0 : s.cells());
    if (cells.empty()) continue;
    for_part_cells(pg, [&](std::size_t q, std::size_t, int i, int j, int k) {
      cells[q] = compact(coords::christoffels(s.coordinates, s.point(i, j, k)));
    });
  }
}

bool SolverGeometry::current_for(const CompositeMultigrid& mg) const {
  if (static_cast<int>(shapes_.size()) != mg.parts()) return false;
  for (int n = 0; n < mg.parts(); ++n)
    if (!same_shape(shapes_[static_cast<std::size_t>(n)], mg.part(n).shape)) return false;
  return true;
}

}  // namespace remnant::xcfc
