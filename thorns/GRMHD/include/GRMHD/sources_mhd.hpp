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

// src has kNumCons entries; src[kD] = src[kDYe] = 0.
inline void gravity_sources_mhd(const FluidState& s, const MagneticState& g, const PointMetric& m, double psi,
                                const MetricDerivatives& dm, const std::array<std::array<double, 3>, 3>& df,
                                const Christoffels* gamma, bool with_shift, double* src) {
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
  for (int j = 0; j < 3; ++j) diag[j] = zt * s.v[j] * s.v[j] - bs[j] * bs[j];
  src[kD] = 0;
  src[kDYe] = 0;
  double tau = 0;
  for (int i = 0; i < 3; ++i) {
    double si = -E * dm.dalpha[i] + two_a_trace_over_psi * dm.dpsi[i] +
                half_a_psi4 * (diag[0] * df[i][0] + diag[1] * df[i][1] + diag[2] * df[i][2]);
    if (with_shift) si += S_dn[0] * dm.dbeta[i][0] + S_dn[1] * dm.dbeta[i][1] + S_dn[2] * dm.dbeta[i][2];
    src[kS1 + i] = si;
    tau -= S_up[i] * dm.dalpha[i];
  }
  if (with_shift) {
    double nb[3][3];  // nabla_i beta^j
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double c = dm.dbeta[i][j];
        if (gamma)
          for (int k = 0; k < 3; ++k) c += (*gamma)[j][i][k] * m.beta[k];
        nb[i][j] = c;
      }
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

// The trace S = S^j_j of the xCFC matter sources: S_i v^i + 3 p + b^2 / 2 (with S_i the conserved
// momentum; reduces to S_i v^i + 3 p without field).
inline double stress_trace_mhd(const FluidState& s, const MagneticState& g) {
  double sv = 0;
  for (int i = 0; i < 3; ++i) sv += ((s.rho * s.h * s.W * s.W + g.B2) * s.v_dn[i] - g.Bv * g.B_dn[i]) * s.v[i];
  return sv + 3.0 * s.press + 0.5 * g.b2;
}

}  // namespace remnant::grmhd
