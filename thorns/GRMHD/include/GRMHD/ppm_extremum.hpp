#pragma once
// Extremum-preserving PPM (GRMHD::reconstruction / emf_reconstruction = ppm_ep): Colella & Sekora
// 2008 (J. Comput. Phys. 227, 7069) with the cell limiter of McCorquodale & Colella 2011 (CAMCoS 6, 1),
// their constant C = 1.25. Classic PPM (reconstruct_ppm) clamps every face value between its two cells
// and flattens each cell that is a local extremum, so a smooth maximum (a star's field on its axis, at
// its centre) is cut to first order and the HLL jumps there dissipate it; here a face value or a
// parabola is limited only where the second derivatives of the neighbourhood disagree in sign, which
// a smooth extremum never triggers (a discontinuity still does). Same stencil as PPM (3 ghost zones);
// conventions of reconstruction.hpp (left[f], right[f] written at faces 0..n only; scratch of
// ppm_scratch_size(n) = n + 3 values for the interface values).
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <span>

namespace remnant::grmhd {

namespace detail {

// sign(d) min(|d|, C |d1|, C |d2|) when d, d1, d2 share their sign, else 0 (CS08 eq. 18, 22).
inline double limited_second_derivative(double d, double d1, double d2, double c) {
  if (!((d > 0 && d1 > 0 && d2 > 0) || (d < 0 && d1 < 0 && d2 < 0))) return 0.0;
  const double m = std::min({std::abs(d), c * std::abs(d1), c * std::abs(d2)});
  return d > 0 ? m : -m;
}

}  // namespace detail

inline void reconstruct_ppm_ep(const double* __restrict q, double* __restrict left, double* __restrict right, int n,
                               std::span<double> scratch) {
  constexpr double C = 1.25;
  assert(scratch.size() >= static_cast<std::size_t>(n) + 3);
  double* a = scratch.data() + 1;  // a[f] for f = -1 .. n+1, between cells f-1 and f
  for (int f = -1; f <= n + 1; ++f) {
    const double lo = q[f - 1], hi = q[f];
    double v = (7.0 / 12.0) * (lo + hi) - (1.0 / 12.0) * (q[f - 2] + q[f + 1]);
    // Outside the range of its two cells: a limited parabola through them (CS08 eq. 16-18).
    if ((v - lo) * (hi - v) < 0) {
      const double d2a = 3.0 * (lo - 2.0 * v + hi);
      const double d2l = q[f - 2] - 2.0 * lo + hi;
      const double d2r = lo - 2.0 * hi + q[f + 1];
      v = 0.5 * (lo + hi) - detail::limited_second_derivative(d2a, d2l, d2r, C) / 6.0;
    }
    a[f] = v;
  }
  for (int c = -1; c <= n; ++c) {
    const double qc = q[c];
    double aL = a[c], aR = a[c + 1];
    const double dm = qc - aL, dp = aR - qc;
    if (dm * dp <= 0 || (qc - q[c - 1]) * (q[c + 1] - qc) <= 0) {
      // A local extremum of the parabola or of the cells: keep its curvature if the neighbourhood
      // agrees on it (MC11 eq. 26-29), else flatten it.
      const double d2 = -12.0 * qc + 6.0 * (aL + aR);
      const double d2c = q[c - 1] - 2.0 * qc + q[c + 1];
      const double d2l = q[c - 2] - 2.0 * q[c - 1] + qc;
      const double d2r = qc - 2.0 * q[c + 1] + q[c + 2];
      double d2lim = 0.0;
      if ((d2 > 0 && d2c > 0 && d2l > 0 && d2r > 0) || (d2 < 0 && d2c < 0 && d2l < 0 && d2r < 0)) {
        const double m = std::min({std::abs(d2), C * std::abs(d2c), C * std::abs(d2l), C * std::abs(d2r)});
        d2lim = d2 > 0 ? m : -m;
      }
      if (d2 != 0) {
        const double ratio = d2lim / d2;
        aL = qc - dm * ratio;
        aR = qc + dp * ratio;
      } else {
        aL = aR = qc;
      }
    } else {
      // Monotone cell: the parabola may not overshoot its own range (CW84 eq. 1.10).
      if (std::abs(dm) >= 2.0 * std::abs(dp)) aL = qc - 2.0 * dp;
      if (std::abs(dp) >= 2.0 * std::abs(dm)) aR = qc + 2.0 * dm;
    }
    // Cell -1 gives left[0] and cell n right[n] only: left and right hold faces 0..n.
    if (c >= 0) right[c] = aL;
    if (c < n) left[c + 1] = aR;
  }
}

}  // namespace remnant::grmhd
