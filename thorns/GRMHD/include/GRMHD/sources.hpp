#pragma once
// Source terms of the reference-metric Valencia equations under CFC (not densitised; the caller
// multiplies by psi^6). With E = tau + D, S_i = rho h W^2 v_i, S^ij = rho h W^2 v^i v^j + p gamma^ij:
//   s(S_i) = -E d_i alpha + S_k d_i beta^k + (alpha/2) S^jk d_i gamma_jk
//   s(tau) =  alpha S^ij K_ij - S^j d_j alpha
// (3+1 energy-momentum conservation with K = 0, e.g. Gourgoulhon 2012, "3+1 Formalism in General
// Relativity", sec. 6.3; the same in Cheong et al. 2020).
// Splitting d_i gamma_jk = 4 psi^3 d_i psi f_jk + psi^4 d_i f_jk gives
//   (alpha/2) S^jk d_i gamma_jk = 2 alpha (S^j_j) d_i psi / psi
//                                + (alpha/2) psi^4 rho h W^2 sum_j (v^j)^2 d_i f_jj   [geometric, velocity]
//                                + alpha p d_i ln sqrt(f)                             [geometric, pressure]
// The pressure part is NOT added here: the caller adds alpha psi^6 p times the exact cell average of
// d_i ln sqrt f, (w_i(+) - w_i(-)) / G_i, so that a uniform pressure is balanced to round-off by the
// face-area-weighted flux divergence.
// Under CFC the extrinsic curvature follows from the shift (Cordero-Carrion et al. 2009, with
// d_t psi from the lapse-shift relation): K^ij = (nabla^i beta^j + nabla^j beta^i - (2/3) f^ij nabla_k beta^k)
// / (2 alpha psi^4), nabla the covariant derivative of f, indices raised with f. Then
//   alpha S_ij K^ij = rho h W^2 (v^i v_j nabla_i beta^j - v^2 nabla_k beta^k / 3).
// TODO(XCFC): take K_ij (or A^ij) from the XCFC solver once it exists.
#include <array>

#include "GRMHD/valencia.hpp"
#include "remnant/coordinates.hpp"

namespace remnant::grmhd {

struct MetricDerivatives {
  std::array<double, 3> dpsi{0, 0, 0}, dalpha{0, 0, 0};
  std::array<std::array<double, 3>, 3> dbeta{};  // dbeta[i][k] = d_i beta^k
};

// nabla_i beta^j = d_i beta^j + Gamma^j_ik beta^k (nabla of the flat metric f; gamma = nullptr:
// Cartesian, no Christoffels), for the extrinsic-curvature term of s(tau).
inline std::array<std::array<double, 3>, 3> shift_gradient(const MetricDerivatives& dm, const Christoffels* gamma,
                                                           const std::array<double, 3>& beta) {
  std::array<std::array<double, 3>, 3> nb;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double c = dm.dbeta[i][j];
      if (gamma)
        for (int k = 0; k < 3; ++k) c += (*gamma)[j][i][k] * beta[k];
      nb[i][j] = c;
    }
  return nb;
}

// s(S_i) less its shift term: -E d_i alpha + (2 alpha S^j_j / psi) d_i psi + k sum_j diag_j d_i f_jj,
// k diag_j the (alpha/2) psi^4 S^jj of the stress (hydro: k = (alpha/2) psi^4 rho h W^2, diag_j = (v^j)^2).
inline double momentum_source_without_shift(int i, double E, double two_a_trace_over_psi, double k, const double* diag,
                                            const MetricDerivatives& dm, const std::array<std::array<double, 3>, 3>& df) {
  return -E * dm.dalpha[i] + two_a_trace_over_psi * dm.dpsi[i] + k * (diag[0] * df[i][0] + diag[1] * df[i][1] + diag[2] * df[i][2]);
}
// w_k d_i beta^k (the shift term of s(S_i) is S_k d_i beta^k).
inline double shift_contraction(int i, const double* w, const MetricDerivatives& dm) {
  return w[0] * dm.dbeta[i][0] + w[1] * dm.dbeta[i][1] + w[2] * dm.dbeta[i][2];
}

// s[kD] and s[kDYe] are zero; `df[i][j]` = d_i f_jj; `with_shift` skips the shift terms when beta = 0.
inline void gravity_sources(const FluidState& s, const PointMetric& m, double psi, const MetricDerivatives& dm,
                            const std::array<std::array<double, 3>, 3>& df, const Christoffels* gamma,
                            bool with_shift, double* src) {
  const double z = s.rho * s.h * s.W * s.W;          // rho h W^2
  const double E = z - s.press;                       // tau + D
  const double trace = z * s.v2 + 3.0 * s.press;      // S^j_j
  const double two_a_trace_over_psi = 2.0 * m.alpha * trace / psi;
  const double half_a_psi4_z = 0.5 * m.alpha * m.psi4 * z;
  const double vv[3] = {s.v[0] * s.v[0], s.v[1] * s.v[1], s.v[2] * s.v[2]};
  src[kD] = 0;
  src[kDYe] = 0;
  double tau = 0;
  for (int i = 0; i < 3; ++i) {
    double si = momentum_source_without_shift(i, E, two_a_trace_over_psi, half_a_psi4_z, vv, dm, df);
    if (with_shift) si += z * shift_contraction(i, s.v_dn.data(), dm);
    src[kS1 + i] = si;
    tau -= z * s.v[i] * dm.dalpha[i];
  }
  if (with_shift) {
    const auto nb = shift_gradient(dm, gamma, m.beta);
    double vvk = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) vvk += s.v[i] * s.v_dn[j] * nb[i][j];
    const double div = nb[0][0] + nb[1][1] + nb[2][2];
    tau += z * (vvk - s.v2 * div / 3.0);
  }
  src[kTau] = tau;
}

}  // namespace remnant::grmhd
