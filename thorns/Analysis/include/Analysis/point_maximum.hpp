#pragma once
// The point value of a density maximum from cell averages (the rho_max_point column).
//
// rho_max is the largest CELL AVERAGE; near a peak the average lies below the peak by about
// (1/2) d2rho/dx2 <x^2>_cell, and <x^2>_cell depends on the cell's shape: the axis cell of a
// cylindrical grid averages a disc with weight R (<R^2> = dx^2/2), the corner cell of a Cartesian
// octant a square (<x^2 + y^2> = 2 dx^2/3). The two geometries' rho_max then differ at O(dx^2)
// even where their solutions agree. The point value removes that bias:
//   rho ~ a + sum_d (g_d x_d + h_d x_d^2),
// fitted exactly to the averages of the maximum cell and of two neighbours along each direction,
// with the exact cell averages of 1, x and x^2 under each cell's volume weight (1 in Cartesian
// directions and cylindrical z, R in cylindrical R); then the maximum of that function over the
// maximum cell. Next to a reflection plane or the axis the lower neighbour is the mirror cell
// (the fit is then even there); at a block edge the three cells shift inwards (one-sided).
// The fit reproduces separable quadratics exactly; at a smooth maximum on the symmetry planes
// (the head-on collision point) the error is O(dx^4), elsewhere O(dx^2) (the cross terms x_d x_e).
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace remnant::analysis {

enum class CellWeight { uniform, radial };  // volume weight along a direction: 1, or R (cylindrical R)

struct CellAverages {  // <x> and <x^2> over [lo, hi] with the weight
  double x, x2;
};
// Also for the mirror [lo, hi] = [-b, -a] of a radial cell [a, b] (weight |R|).
CellAverages cell_averages(CellWeight w, double lo, double hi);

struct StencilCell {
  double lo = 0, hi = 0, value = 0;
};
struct DirectionStencil {
  CellWeight weight = CellWeight::uniform;
  double lo = 0, hi = 0;  // the maximum cell
  std::array<StencilCell, 2> others;
};

// The maximum over the centre cell of the fitted separable quadratic (see above); NaN when a
// direction's three cells do not determine it (degenerate cells).
double point_maximum(double centre_value, std::span<const DirectionStencil> directions);

// The cells of one block along a used direction: faces[0..n] of its n interior cells, and whether
// faces[0] is a reflection plane or the axis (the mirror cell is then the lower neighbour of cell 0).
struct CellLine {
  CellWeight weight = CellWeight::uniform;
  std::span<const double> faces;
  bool symmetric_lower = false;
};

// point_maximum for cell `cell` of a block, value(i, j, k) reading its interior cells (the unused
// directions' indices stay at cell[d]). NaN where a line has fewer than three cells and no mirror.
template <class Value>
double point_maximum_at(std::span<const CellLine> lines, std::array<int, 3> cell, Value&& value) {
  std::array<DirectionStencil, 3> st{};
  const double v0 = value(cell[0], cell[1], cell[2]);
  for (std::size_t d = 0; d < lines.size(); ++d) {
    const CellLine& l = lines[d];
    const int n = static_cast<int>(l.faces.size()) - 1, i = cell[d];
    DirectionStencil& s = st[d];
    s.weight = l.weight;
    s.lo = l.faces[static_cast<std::size_t>(i)], s.hi = l.faces[static_cast<std::size_t>(i) + 1];
    auto neighbour = [&](int o) {
      std::array<int, 3> c = cell;
      c[d] += o;
      const auto ic = static_cast<std::size_t>(c[d]);
      return StencilCell{l.faces[ic], l.faces[ic + 1], value(c[0], c[1], c[2])};
    };
    if (i == 0 && l.symmetric_lower && n >= 2) {
      s.others = {StencilCell{-s.hi, -s.lo, v0}, neighbour(1)};
    } else if (n < 3) {
      return std::numeric_limits<double>::quiet_NaN();
    } else {
      const int first = i == 0 ? 1 : (i == n - 1 ? -2 : -1);  // the two others: first, first + 1 (skipping 0)
      const int second = first == -1 ? 1 : first + 1;
      s.others = {neighbour(first), neighbour(second)};
    }
  }
  return point_maximum(v0, std::span<const DirectionStencil>(st.data(), lines.size()));
}

}  // namespace remnant::analysis
