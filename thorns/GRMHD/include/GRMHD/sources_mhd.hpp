#pragma once
// The gravitational and geometric sources of sources.hpp with the magnetised stress tensor
//   T^{mu nu} = (rho h + b^2) u^mu u^nu + p_tot g^{mu nu} - b^mu b^nu,   p_tot = p + b^2 / 2,
// whose 3+1 parts are E = tau + D, S_i (conserved_mhd) and
//   S^ij = (rho h + b^2) W^2 v^i v^j + p_tot gamma^ij - bs^i bs^j,  bs^i = B^i / W + W (B.v) v^i
// (bs the spatial projection of b). The same split as sources.hpp: S^jk d_i gamma_jk gives
//   2 alpha S^j_j d_i psi / psi + (alpha/2) psi^4 sum_j (zt (v^j)^2 - (bs^j)^2) d_i f_jj
//   + alpha p_tot d_i ln sqrt f (added by the caller with the exact cell average, as for hydro),
// S^j_j = zt v^2 + 3 p_tot - bs^2, and with the traceless CFC K^ij,
//   alpha S_ij K^ij = zt (v^i v_j nabla_i beta^j - v^2 div beta / 3) - (bs^i bs_j nabla_i beta^j - bs^2 div beta / 3).
// The induction equation has no source in this form (the divergence of an antisymmetric tensor).
#include <array>

#include "GRMHD/sources.hpp"
#include "GRMHD/valencia_mhd.hpp"

namespace remnant::grmhd {

// The total pressure p + b^2 / 2 (what the caller's pressure part of the geometric source takes).
inline double total_pressure(const FluidState& s, const MagneticState& g) { return s.press + 0.5 * g.b2; }

// src has kNumCons entries; src[kD] = src[kDYe] = 0. point_magnetic_geometry = false leaves out the
// magnetic part of the geometric source, -(alpha/2) psi^4 sum_j (bs^j)^2 d_i f_jj, for a caller that
// adds it with exact cell averages (magnetic_geometric_source below).
inline void gravity_sources_mhd(const FluidState& s, const MagneticState& g, const PointMetric& m, double psi,
                                const MetricDerivatives& dm, const std::array<std::array<double, 3>, 3>& df,
                                const Christoffels* gamma, bool with_shift, double* src,
                                bool point_magnetic_geometry = true) {
  const double W2 = s.W * s.W;
  const double z = s.rho * s.h * W2;
  const double zt = z + g.b2 * W2;                    // (rho h + b^2) W^2
  const double ptot = total_pressure(s, g);
  const double wbv = s.W * g.Bv;
  const std::array<double, 3> bs = spatial_b(s, g);
  std::array<double, 3> bs_dn;
  for (int i = 0; i < 3; ++i) bs_dn[i] = m.g_dn[i] * bs[i];
  const double bs2 = g.b2 + wbv * wbv;                // gamma_ij bs^i bs^j
  double S_dn[3], S_up[3];
  for (int i = 0; i < 3; ++i) {
    S_dn[i] = (z + g.B2) * s.v_dn[i] - g.Bv * g.B_dn[i];
    S_up[i] = (z + g.B2) * s.v[i] - g.Bv * g.B[i];
  }
  const double E = zt - ptot - wbv * wbv;             // tau + D
  const double trace = zt * s.v2 + 3.0 * ptot - bs2;  // S^j_j
  const double two_a_trace_over_psi = 2.0 * m.alpha * trace / psi;
  const double half_a_psi4 = 0.5 * m.alpha * m.psi4;
  double diag[3];
  for (int j = 0; j < 3; ++j) diag[j] = zt * s.v[j] * s.v[j] - (point_magnetic_geometry ? bs[j] * bs[j] : 0.0);
  src[kD] = 0;
  src[kDYe] = 0;
  double tau = 0;
  for (int i = 0; i < 3; ++i) {
    double si = momentum_source_without_shift(i, E, two_a_trace_over_psi, half_a_psi4, diag, dm, df);
    if (with_shift) si += shift_contraction(i, S_dn, dm);
    src[kS1 + i] = si;
    tau -= S_up[i] * dm.dalpha[i];
  }
  if (with_shift) {
    const auto nb = shift_gradient(dm, gamma, m.beta);  // nabla_i beta^j
    double vvk = 0, bbk = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        vvk += s.v[i] * s.v_dn[j] * nb[i][j];
        bbk += bs[i] * bs_dn[j] * nb[i][j];
      }
    const double div = nb[0][0] + nb[1][1] + nb[2][2];
    tau += zt * (vvk - s.v2 * div / 3.0) - (bbk - bs2 * div / 3.0);
  }
  src[kTau] = tau;
}

// The magnetic part of the geometric source of S_i, -alpha sum_j gamma_jj (bs^j)^2 d_i ln sqrt f_jj,
// with d_i ln sqrt f_jj replaced by its share of `log_area_derivative`, the exact cell average of
// d_i ln sqrt f ((A+ - A-)/V of the cell): the share of direction j is (d_i f_jj / f_jj) / sum_k (d_i f_kk / f_kk)
// at the centroid (1/2 each for theta and phi in spherical r, otherwise 1 or 0). As for the pressure,
// this keeps the singular 1/r, cot(theta) factors consistent with the face-area flux divergence at
// the axis and the origin, where the point values leave an O(1/dx) imbalance in the first cell.
inline double magnetic_geometric_source(int i, const FluidState& s, const MagneticState& g, const PointMetric& m,
                                        const std::array<double, 3>& f, const std::array<std::array<double, 3>, 3>& df,
                                        double log_area_derivative) {
  double sum = 0, weighted = 0;
  const std::array<double, 3> bs = spatial_b(s, g);
  for (int j = 0; j < 3; ++j) {
    const double l = df[i][j] / f[j];
    sum += l;
    weighted += m.g_dn[j] * bs[j] * bs[j] * l;
  }
  if (sum == 0) return 0.0;
  return -m.alpha * log_area_derivative * weighted / sum;
}

// The trace S = S^j_j of the xCFC matter sources: S_i v^i + 3 p + b^2 / 2 (with S_i the conserved
// momentum; reduces to S_i v^i + 3 p without field).
inline double stress_trace_mhd(const FluidState& s, const MagneticState& g) {
  double sv = 0;
  for (int i = 0; i < 3; ++i) sv += ((s.rho * s.h * s.W * s.W + g.B2) * s.v_dn[i] - g.Bv * g.B_dn[i]) * s.v[i];
  return sv + 3.0 * s.press + 0.5 * g.b2;
}

}  // namespace remnant::grmhd
