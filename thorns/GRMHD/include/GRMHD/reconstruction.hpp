#pragma once
// One-dimensional reconstruction of cell averages to the two sides of every face of a line.
// Convention: q[c] is cell c (ghosts at negative c and c >= n); face f lies between cells f-1 and f.
// left[f] is the state just left of face f (right edge of cell f-1), right[f] the state just right
// of it (left edge of cell f), for f = 0..n. PPM needs 3 ghost cells, MC and minmod need 2 (q is
// read at -3 .. n+2, resp. -2 .. n+1). left and right are written at 0..n only: arrays of exactly
// n + 1 values are enough. PPM's interface values go to a scratch span of ppm_scratch_size(n).
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <span>
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

// The scratch PPM needs for a line of n cells: its interface values a[-1 .. n+1].
constexpr std::size_t ppm_scratch_size(int n) { return static_cast<std::size_t>(n) + 3; }

namespace detail {

// CW84 eq. 1.10 for a cell of value qc and interface values aL, aR: its constrained edge values
// edge_lo (right[c]) and edge_hi (left[c + 1]), as selects (the values of the branches), so that the loop vectorises.
[[gnu::always_inline]] inline void ppm_constrain(double qc, double aL, double aR, double& edge_lo, double& edge_hi) {
  const bool extremum = (aR - qc) * (qc - aL) <= 0;  // local extremum: flat
  const double d = aR - aL, m6 = 6.0 * (qc - 0.5 * (aL + aR));
  // Never both: d m6 > d^2 >= 0 > -d^2 (and neither for NaN), so the branches' else-if order is kept.
  const bool steep_left = d * m6 > d * d;
  const bool steep_right = -d * d > d * m6;
  edge_lo = extremum ? qc : steep_left ? 3.0 * qc - 2.0 * aR : aL;
  edge_hi = extremum ? qc : steep_right ? 3.0 * qc - 2.0 * aL : aR;
}

}  // namespace detail

// PPM of Colella & Woodward (1984): fourth-order face values limited to the neighbouring cells,
// then the parabola's monotonicity constraints (their eqs. 1.10). No steepening or flattening.
// Cell -1 gives left[0] and cell n right[n]: their other edges are not stored (left and right hold
// faces 0..n only).
// (__restrict: the arrays never overlap, which spares the vectorised loops their overlap checks.)
inline void reconstruct_ppm(const double* __restrict q, double* __restrict left, double* __restrict right, int n,
                            std::span<double> scratch) {
  assert(scratch.size() >= ppm_scratch_size(n));
  double* __restrict a = scratch.data() + 1;  // a[f] for f = -1 .. n+1
  for (int f = -1; f <= n + 1; ++f) {
    const double lo = q[f - 1], hi = q[f];
    double v = (7.0 / 12.0) * (lo + hi) - (1.0 / 12.0) * (q[f - 2] + q[f + 1]);
    v = std::clamp(v, std::min(lo, hi), std::max(lo, hi));
    a[f] = v;
  }
  double unused;
  detail::ppm_constrain(q[-1], a[-1], a[0], unused, left[0]);
  for (int c = 0; c < n; ++c) detail::ppm_constrain(q[c], a[c], a[c + 1], right[c], left[c + 1]);
  detail::ppm_constrain(q[n], a[n], a[n + 1], right[n], unused);
}

// scratch: ppm_scratch_size(n) values for PPM (unused by MC and minmod).
inline void reconstruct(Reconstruction r, const double* q, double* left, double* right, int n, std::span<double> scratch) {
  switch (r) {
    case Reconstruction::ppm: reconstruct_ppm(q, left, right, n, scratch); break;
    case Reconstruction::mc: reconstruct_plm<true>(q, left, right, n); break;
    case Reconstruction::minmod: reconstruct_plm<false>(q, left, right, n); break;
    case Reconstruction::ppm_ep: reconstruct_ppm_ep(q, left, right, n, scratch); break;
  }
}

}  // namespace remnant::grmhd
