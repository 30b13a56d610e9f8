#pragma once
// Slope limiters shared by reconstruction and prolongation.
#include <algorithm>
#include <cmath>

namespace remnant {

// Monotonised-central slope from three values at (non-uniformly spaced) points xm < x0 < xp:
// zero at extrema, otherwise the smallest of the centred and twice the one-sided slopes.
inline double mc_slope(double um, double u0, double up, double xm, double x0, double xp) {
  const double dl = (u0 - um) / (x0 - xm), dr = (up - u0) / (xp - x0);
  if (!(dl * dr > 0)) return 0.0;
  const double dc = (up - um) / (xp - xm);
  const double m = std::min({std::abs(dc), 2 * std::abs(dl), 2 * std::abs(dr)});
  return dc > 0 ? m : -m;
}

}  // namespace remnant
