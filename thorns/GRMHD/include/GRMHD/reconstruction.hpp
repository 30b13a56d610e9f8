#pragma once
// One-dimensional reconstruction of cell averages to the two sides of every face of a line.
// Convention: q[c] is cell c (ghosts at negative c and c >= n); face f lies between cells f-1 and f.
// left[f] is the state just left of face f (right edge of cell f-1), right[f] the state just right
// of it (left edge of cell f), for f = 0..n. PPM needs 3 ghost cells, MC and minmod need 2, and PPM
// writes right[-1] and left[n + 1] as scratch (the arrays need one slot more on each side).
#include <algorithm>
#include <cmath>
#include <string>

#include "GRMHD/ppm_extremum.hpp"

namespace remnant::grmhd {

enum class Reconstruction { ppm, mc, minmod, ppm_ep };

inline Reconstruction parse_reconstruction(const std::string& s) {
  if (s == "mc") return Reconstruction::mc;
  if (s == "minmod") return Reconstruction::minmod;
  if (s == "ppm_ep") return Reconstruction::ppm_ep;
  return Reconstruction::ppm;
}
inline int ghosts_needed(Reconstruction r) {
  return r == Reconstruction::ppm || r == Reconstruction::ppm_ep ? 3 : 2;
}

namespace detail {

inline double minmod(double a, double b) {
  return a * b <= 0 ? 0.0 : (std::abs(a) < std::abs(b) ? a : b);
}
// Monotonised central limiter (van Leer 1977).
inline double mc_slope(double dm, double dp) {
  if (dm * dp <= 0) return 0.0;
  const double s = dm > 0 ? 1.0 : -1.0;
  return s * std::min({2.0 * std::abs(dm), 2.0 * std::abs(dp), 0.5 * std::abs(dm + dp)});
}

}  // namespace detail

// Piecewise-linear reconstruction with the MC or minmod slope.
template <bool UseMC>
inline void reconstruct_plm(const double* q, double* left, double* right, int n) {
  for (int c = -1; c <= n; ++c) {
    const double dm = q[c] - q[c - 1], dp = q[c + 1] - q[c];
    const double half = 0.5 * (UseMC ? detail::mc_slope(dm, dp) : detail::minmod(dm, dp));
    if (c >= 0) right[c] = q[c] - half;
    if (c < n) left[c + 1] = q[c] + half;
  }
}

// PPM of Colella & Woodward (1984): fourth-order face values limited to the neighbouring cells,
// then the parabola's monotonicity constraints (their eqs. 1.10). No steepening or flattening.
// `face` is scratch for n + 3 values.
// (__restrict: the four arrays never overlap, which spares the vectorised loops their overlap checks.)
inline void reconstruct_ppm(const double* __restrict q, double* __restrict left, double* __restrict right, int n,
                            double* __restrict face) {
  double* a = face + 1;  // a[f] for f = -1 .. n+1
  for (int f = -1; f <= n + 1; ++f) {
    const double lo = q[f - 1], hi = q[f];
    double v = (7.0 / 12.0) * (lo + hi) - (1.0 / 12.0) * (q[f - 2] + q[f + 1]);
    v = std::clamp(v, std::min(lo, hi), std::max(lo, hi));
    a[f] = v;
  }
  // The monotonicity constraints as selects (the values of the branches of CW84 eq. 1.10), so that
  // the loop vectorises; right[-1] and left[n + 1] are scratch (LineScratch allocates them).
  for (int c = -1; c <= n; ++c) {
    const double qc = q[c];
    const double aL = a[c], aR = a[c + 1];
    const bool extremum = (aR - qc) * (qc - aL) <= 0;  // local extremum: flat
    const double d = aR - aL, m6 = 6.0 * (qc - 0.5 * (aL + aR));
    // Never both: d m6 > d^2 >= 0 > -d^2 (and neither for NaN), so the branches' else-if order is kept.
    const bool steep_left = d * m6 > d * d;
    const bool steep_right = -d * d > d * m6;
    right[c] = extremum ? qc : steep_left ? 3.0 * qc - 2.0 * aR : aL;
    left[c + 1] = extremum ? qc : steep_right ? 3.0 * qc - 2.0 * aL : aR;
  }
}

inline void reconstruct(Reconstruction r, const double* q, double* left, double* right, int n, double* scratch) {
  switch (r) {
    case Reconstruction::ppm: reconstruct_ppm(q, left, right, n, scratch); break;
    case Reconstruction::mc: reconstruct_plm<true>(q, left, right, n); break;
    case Reconstruction::minmod: reconstruct_plm<false>(q, left, right, n); break;
    case Reconstruction::ppm_ep: reconstruct_ppm_ep(q, left, right, n, scratch); break;
  }
}

}  // namespace remnant::grmhd
