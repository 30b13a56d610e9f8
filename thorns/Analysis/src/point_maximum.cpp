#include "Analysis/point_maximum.hpp"

#include <algorithm>

namespace remnant::analysis {

CellAverages cell_averages(CellWeight w, double lo, double hi) {
  if (w == CellWeight::uniform) return {0.5 * (lo + hi), (lo * lo + lo * hi + hi * hi) / 3};
  if (hi <= 0) {  // the mirror of [-hi, -lo]: weight |R|, odd moment changes sign
    const CellAverages m = cell_averages(w, -hi, -lo);
    return {-m.x, m.x2};
  }
  // int R^(n+1) dR / int R dR over [lo, hi]
  return {2 * (hi * hi * hi - lo * lo * lo) / (3 * (hi * hi - lo * lo)), 0.5 * (lo * lo + hi * hi)};
}

double point_maximum(double centre_value, std::span<const DirectionStencil> directions) {
  double a = centre_value, peak = 0;
  for (const DirectionStencil& s : directions) {
    const CellAverages c = cell_averages(s.weight, s.lo, s.hi);
    // v_k - v_0 = g (<x>_k - <x>_0) + h (<x^2>_k - <x^2>_0): the other directions' terms cancel.
    double m[2][2], r[2];
    for (std::size_t k = 0; k < 2; ++k) {
      const CellAverages o = cell_averages(s.weight, s.others[k].lo, s.others[k].hi);
      m[k][0] = o.x - c.x, m[k][1] = o.x2 - c.x2, r[k] = s.others[k].value - centre_value;
    }
    const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    const double scale = std::abs(m[0][0] * m[1][1]) + std::abs(m[0][1] * m[1][0]);
    if (!(std::abs(det) > 1e-12 * scale)) return std::numeric_limits<double>::quiet_NaN();
    const double g = (r[0] * m[1][1] - r[1] * m[0][1]) / det, h = (m[0][0] * r[1] - m[1][0] * r[0]) / det;
    a -= g * c.x + h * c.x2;
    // The largest value of g x + h x^2 within the cell: an end, or the vertex of a cap inside.
    double best = std::max(g * s.lo + h * s.lo * s.lo, g * s.hi + h * s.hi * s.hi);
    if (h < 0) {
      const double xv = -g / (2 * h);
      if (xv > s.lo && xv < s.hi) best = std::max(best, g * xv + h * xv * xv);
    }
    peak += best;
  }
  return a + peak;
}

}  // namespace remnant::analysis
