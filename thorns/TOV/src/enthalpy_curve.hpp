#pragma once
// H(ln rho) = int dp / (e + p) of a cold slice given as smooth pieces (between the kinks of an
// interpolated table), and its inverse, consistent to O(h^3) in the derivative: dp/dH = e + p holds
// along the slice wherever rho(H) is evaluated. (A monotone spline of ln rho(H) has a first-order
// derivative at the ends of its pieces: 0.3 % at the SFHo table's nodes, a force that a static star's
// evolution feels as a pulse from every node.)
//   In each piece the samples are uniform in x = ln rho: dp/dx by fourth-order differences inside the
//   piece, H by fourth-order quadrature of g = (dp/dx) / (e + p), and H(x) between two samples the
//   cubic Hermite interpolant of (H, g); x(H) inverts that same cubic.
#include <cstddef>
#include <vector>

namespace remnant::tov {

struct SlicePiece {
  double x0 = 0, dx = 0;          // x_j = x0 + j dx, j = 0 .. p.size() - 1 (at least 5 points)
  std::vector<double> p, e;       // pressure and total energy density rho (1 + eps) at x_j
};

class EnthalpyCurve {
 public:
  explicit EnthalpyCurve(const std::vector<SlicePiece>& pieces);  // ascending, each starting where the last ended
  double H(double x) const;      // clamped to the curve's range
  double x_of(double H) const;   // clamped likewise
  double H_max() const { return pieces_.back().H.back(); }

 private:
  struct Piece {
    double x0, dx;
    std::vector<double> H, g;  // H and dH/dx at the samples
  };
  std::size_t piece_of_x(double x) const;
  std::size_t piece_of_H(double H) const;
  std::vector<Piece> pieces_;
};

}  // namespace remnant::tov
