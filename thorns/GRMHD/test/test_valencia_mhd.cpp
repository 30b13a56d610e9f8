// Pointwise ideal GRMHD (GRMHD/valencia_mhd.hpp, sources_mhd.hpp):
// - with B = 0 the conserved variables, fluxes and speeds are the bits of the hydro functions;
// - the conserved variables agree with Con2Prim's prim_to_cons (the recovery must invert them);
// - the conserved variables and fluxes of random boosted magnetised states in a random CFC metric
//   (lapse, shift, psi, f) agree with an independent covariant evaluation from T^{mu nu} and the
//   dual Faraday tensor built from u^mu, b^mu and the 4-metric;
// - the signal speeds equal the exact fast speed for b normal to the direction (at rest and boosted
//   along it, relativistic velocity addition) and bound max(cs, va) for b along it;
// - the sources of a static magnetised state in cylindrical coordinates vs a hand calculation, and
//   the xCFC trace S = S^j_j vs the covariant trace.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "Con2Prim/prim_to_cons.hpp"
#include "GRMHD/sources_mhd.hpp"
#include "GRMHD/valencia_mhd.hpp"

namespace {

using namespace remnant::grmhd;
using M4 = std::array<std::array<double, 4>, 4>;

struct Sample {
  PointMetric m;
  FluidState s;
  MagneticState g;
  double psi = 1;
};

// A random metric (diagonal f, psi, lapse, shift) and a random magnetised state with W up to ~3.
Sample random_sample(std::mt19937& rng, bool with_field = true, bool with_shift = true) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0.5, 2.0);
  Sample q;
  q.psi = pos(rng);
  const std::array<double, 3> f{pos(rng), pos(rng), pos(rng)};
  const std::array<double, 3> beta = with_shift ? std::array<double, 3>{0.2 * u(rng), 0.2 * u(rng), 0.2 * u(rng)}
                                                : std::array<double, 3>{0, 0, 0};
  q.m = point_metric(q.psi, 0.5 + 0.5 * pos(rng), beta, f);
  q.s.rho = pos(rng);
  q.s.press = 0.3 * pos(rng);
  q.s.eps = 1.5 * q.s.press / q.s.rho;
  q.s.h = 1 + q.s.eps + q.s.press / q.s.rho;
  q.s.cs2 = 0.3 * pos(rng) / 2.0;
  q.s.ye = 0.1;
  set_velocity_from_wv(q.s, q.m, 1.5 * u(rng), 1.5 * u(rng), 1.5 * u(rng));
  const double s = with_field ? 1.0 : 0.0;
  q.g = magnetic_state(q.s, q.m, s * u(rng), s * u(rng), s * u(rng));
  return q;
}

TEST(ValenciaMHD, ZeroFieldGivesTheHydroBits) {
  std::mt19937 rng(11);
  for (int n = 0; n < 200; ++n) {
    const Sample q = random_sample(rng, false);
    double uh[kNumCons], um[kNumMhd];
    conserved(q.s, uh);
    conserved_mhd(q.s, q.g, um);
    for (int c = 0; c < kNumCons; ++c) EXPECT_EQ(uh[c], um[c]) << c;
    for (int d = 0; d < 3; ++d) {
      double fh[kNumCons], fm[kNumMhd];
      flux(d, q.s, q.m, uh, fh);
      flux_mhd(d, q.s, q.g, q.m, um, fm);
      for (int c = 0; c < kNumCons; ++c) EXPECT_EQ(fh[c], fm[c]) << d << " " << c;
      for (int c = kB1; c <= kB3; ++c) EXPECT_EQ(fm[c], 0.0);
      double lmh, lph, lmm, lpm;
      characteristic_speeds(d, q.s, q.m, lmh, lph);
      characteristic_speeds_mhd(d, q.s, q.g, q.m, lmm, lpm);
      EXPECT_EQ(lmh, lmm);
      EXPECT_EQ(lph, lpm);
    }
    // The sources regroup products (not bitwise): round-off only.
    MetricDerivatives dm;
    std::uniform_real_distribution<double> u(-1, 1);
    std::array<std::array<double, 3>, 3> df{};
    for (int i = 0; i < 3; ++i) {
      dm.dpsi[i] = u(rng);
      dm.dalpha[i] = u(rng);
      for (int k = 0; k < 3; ++k) {
        dm.dbeta[i][k] = u(rng);
        df[i][k] = u(rng);
      }
    }
    double sh[kNumCons], sm[kNumCons];
    gravity_sources(q.s, q.m, q.psi, dm, df, nullptr, true, sh);
    gravity_sources_mhd(q.s, q.g, q.m, q.psi, dm, df, nullptr, true, sm);
    for (int c = 0; c < kNumCons; ++c) EXPECT_NEAR(sh[c], sm[c], 1e-13 * (1 + std::abs(sh[c]))) << c;
  }
}

TEST(ValenciaMHD, ConservedAgreeWithCon2Prim) {
  std::mt19937 rng(12);
  for (int n = 0; n < 200; ++n) {
    const Sample q = random_sample(rng);
    using namespace remnant::con2prim;
    const Metric3 g3 = Metric3::from_lower(q.m.g_dn[0], 0, 0, q.m.g_dn[1], 0, q.m.g_dn[2]);
    Primitives p;
    p.rho = q.s.rho;
    p.v = q.s.v;
    p.W = q.s.W;
    p.eps = q.s.eps;
    p.press = q.s.press;
    p.ye = q.s.ye;
    p.B = q.g.B;
    const Conserved c = prim_to_cons(p, g3);
    double u[kNumMhd];
    conserved_mhd(q.s, q.g, u);
    const double tol = 1e-13;
    EXPECT_NEAR(u[kD], c.D, tol * c.D);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(u[kS1 + i], c.S[i], tol * (1 + std::abs(c.S[i])));
    EXPECT_NEAR(u[kTau], c.tau, tol * (1 + std::abs(c.tau)));
    EXPECT_NEAR(q.g.b2, b_squared(p, g3), tol * (1 + q.g.b2));
  }
}

// The 4-metric g_{mu nu} and its inverse for lapse, shift and diagonal gamma_ij.
void four_metric(const PointMetric& m, M4& g, M4& gi) {
  g = {};
  gi = {};
  double b_dn[3];
  for (int i = 0; i < 3; ++i) b_dn[i] = m.g_dn[i] * m.beta[i];
  g[0][0] = -m.alpha * m.alpha + (b_dn[0] * m.beta[0] + b_dn[1] * m.beta[1] + b_dn[2] * m.beta[2]);
  for (int i = 0; i < 3; ++i) {
    g[0][i + 1] = g[i + 1][0] = b_dn[i];
    g[i + 1][i + 1] = m.g_dn[i];
  }
  const double ia2 = 1.0 / (m.alpha * m.alpha);
  gi[0][0] = -ia2;
  for (int i = 0; i < 3; ++i) {
    gi[0][i + 1] = gi[i + 1][0] = m.beta[i] * ia2;
    for (int j = 0; j < 3; ++j) gi[i + 1][j + 1] = (i == j ? m.g_up[i] : 0.0) - m.beta[i] * m.beta[j] * ia2;
  }
}

TEST(ValenciaMHD, ConservedAndFluxesMatchTheCovariantStressTensor) {
  std::mt19937 rng(13);
  for (int n = 0; n < 200; ++n) {
    const Sample q = random_sample(rng);
    const PointMetric& m = q.m;
    const FluidState& s = q.s;
    M4 g, gi;
    four_metric(m, g, gi);
    // u^mu = W (1/alpha, v^i - beta^i/alpha); b^mu from B^i.
    std::array<double, 4> uu{s.W / m.alpha, 0, 0, 0}, bu{};
    for (int i = 0; i < 3; ++i) uu[i + 1] = s.W * (s.v[i] - m.beta[i] / m.alpha);
    const double Bv = q.g.B[0] * s.v_dn[0] + q.g.B[1] * s.v_dn[1] + q.g.B[2] * s.v_dn[2];
    bu[0] = s.W * Bv / m.alpha;
    for (int i = 0; i < 3; ++i) bu[i + 1] = (q.g.B[i] + m.alpha * bu[0] * uu[i + 1]) / s.W;
    std::array<double, 4> bd{};
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c) bd[a] += g[a][c] * bu[c];
    double b2 = 0;
    for (int a = 0; a < 4; ++a) b2 += bu[a] * bd[a];
    EXPECT_NEAR(b2, q.g.b2, 1e-12 * (1 + b2));
    const double ptot = s.press + 0.5 * b2, w = s.rho * s.h + b2;
    M4 T{};  // T^{mu nu}
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c) T[a][c] = w * uu[a] * uu[c] + ptot * gi[a][c] - bu[a] * bu[c];
    auto T_mixed = [&](int a, int c) {  // T^a_c
      double r = 0;
      for (int e = 0; e < 4; ++e) r += T[a][e] * g[e][c];
      return r;
    };
    double u[kNumMhd];
    conserved_mhd(s, q.g, u);
    const double D = s.rho * s.W;
    const double tol = 1e-11;
    EXPECT_NEAR(u[kTau], m.alpha * m.alpha * T[0][0] - D, tol * (1 + std::abs(u[kTau])));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(u[kS1 + i], m.alpha * T_mixed(0, i + 1), tol * (1 + std::abs(u[kS1 + i])));
    for (int d = 0; d < 3; ++d) {
      double f[kNumMhd];
      flux_mhd(d, s, q.g, m, u, f);
      const double vt = m.alpha * s.v[d] - m.beta[d];
      EXPECT_NEAR(f[kD], D * vt, tol);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(f[kS1 + i], m.alpha * T_mixed(d + 1, i + 1), tol * (1 + std::abs(f[kS1 + i]))) << d << i;
      EXPECT_NEAR(f[kTau], m.alpha * m.alpha * T[0][d + 1] - D * vt, tol * (1 + std::abs(f[kTau])));
      // The induction flux alpha (b^i u^d - b^d u^i) (the dual Faraday tensor).
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(f[kB1 + i], m.alpha * (bu[i + 1] * uu[d + 1] - bu[d + 1] * uu[i + 1]), tol) << d << i;
    }
    // The xCFC trace S^j_j = gamma_ij S^ij with S^ij = gamma^i_mu gamma^j_nu T^{mu nu}, gamma^i_0 = beta^i.
    double trace = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double Sij = T[i + 1][j + 1] + m.beta[i] * T[0][j + 1] + m.beta[j] * T[i + 1][0] +
                           m.beta[i] * m.beta[j] * T[0][0];
        trace += g[i + 1][j + 1] * Sij;
      }
    EXPECT_NEAR(stress_trace_mhd(s, q.g), trace, 1e-11 * (1 + std::abs(trace)));
  }
}

// A flat-space state at rest or moving along x, with an ideal-gas-like sound speed.
Sample flat_state(double vx, std::array<double, 3> B) {
  Sample q;
  q.m = point_metric(1.0, 1.0, {0, 0, 0}, {1, 1, 1});
  q.s.rho = 1.0;
  q.s.press = 0.5;
  q.s.eps = 1.5 * q.s.press;
  q.s.h = 1 + q.s.eps + q.s.press;
  q.s.cs2 = (5.0 / 3.0) * q.s.press / (q.s.rho * q.s.h);
  const double W = 1 / std::sqrt(1 - vx * vx);
  set_velocity_from_wv(q.s, q.m, W * vx, 0, 0);
  q.g = magnetic_state(q.s, q.m, B[0], B[1], B[2]);
  return q;
}

TEST(ValenciaMHD, FastSpeedNormalToTheFieldIsExact) {
  for (double vx : {0.0, 0.6, -0.9}) {
    const Sample q = flat_state(vx, {0.0, 1.3, 0.4});
    // Comoving fast speed for k normal to b: a^2 = cs^2 + va^2 - cs^2 va^2 (exact), with b^2 the
    // comoving field, B^2 / W^2 here (B normal to v).
    const double b2 = (1.3 * 1.3 + 0.4 * 0.4) * (1 - vx * vx);
    const double va2 = b2 / (q.s.rho * q.s.h + b2), cs2 = q.s.cs2;
    const double a = std::sqrt(cs2 + va2 - cs2 * va2);
    double lm, lp;
    characteristic_speeds_mhd(0, q.s, q.g, q.m, lm, lp);
    EXPECT_NEAR(lp, (vx + a) / (1 + vx * a), 1e-14);
    EXPECT_NEAR(lm, (vx - a) / (1 - vx * a), 1e-14);
  }
}

TEST(ValenciaMHD, FastSpeedAlongTheFieldBoundsSoundAndAlfven) {
  for (double Bx : {0.2, 1.0, 5.0}) {
    const Sample q = flat_state(0.0, {Bx, 0, 0});
    const double va = std::sqrt(Bx * Bx / (q.s.rho * q.s.h + Bx * Bx)), cs = std::sqrt(q.s.cs2);
    double lm, lp;
    characteristic_speeds_mhd(0, q.s, q.g, q.m, lm, lp);
    EXPECT_GE(lp, std::max(cs, va));  // the exact fast speed along b is max(cs, va)
    EXPECT_LT(lp, 1.0);
    EXPECT_DOUBLE_EQ(lm, -lp);
  }
}

// A static field in cylindrical coordinates (R, z, phi) with gradients of psi and alpha: the sources
// by hand. B = (0, Bz, Bphi) coordinate components, v = 0, beta = 0.
TEST(ValenciaMHD, SourcesOfAStaticMagnetisedStateByHand) {
  const double R = 0.7, psi = 1.3, alpha = 0.8, Bz = 0.3, Bphi = 0.9;
  const std::array<double, 3> f{1.0, 1.0, R * R};
  const PointMetric m = point_metric(psi, alpha, {0, 0, 0}, f);
  FluidState s;
  s.rho = 2.0;
  s.press = 0.4;
  s.eps = 0.3;
  s.h = 1 + s.eps + s.press / s.rho;
  set_velocity_from_wv(s, m, 0, 0, 0);
  const MagneticState g = magnetic_state(s, m, 0, Bz, Bphi);
  MetricDerivatives dm;
  dm.dpsi = {0.11, -0.05, 0};
  dm.dalpha = {0.07, 0.02, 0};
  std::array<std::array<double, 3>, 3> df{};  // d_i f_jj: only d_R f_phiphi = 2 R
  df[0][2] = 2 * R;
  double src[kNumCons];
  gravity_sources_mhd(s, g, m, psi, dm, df, nullptr, false, src);
  const double p4 = std::pow(psi, 4);
  const double B2 = p4 * (Bz * Bz + R * R * Bphi * Bphi);  // b^2 = B^2 at rest
  const double E = s.rho * (1 + s.eps) + 0.5 * B2;
  const double trace = 3 * s.press + 0.5 * B2;  // 3 p_tot - b^2
  for (int i = 0; i < 2; ++i) {
    double expect = -E * dm.dalpha[i] + 2 * alpha * trace * dm.dpsi[i] / psi;
    if (i == 0) expect += -0.5 * alpha * p4 * Bphi * Bphi * 2 * R;  // hoop stress -alpha psi^4 R (B^phi)^2
    EXPECT_NEAR(src[kS1 + i], expect, 1e-14) << i;
  }
  EXPECT_NEAR(src[kS3], 0.0, 1e-15);
  EXPECT_NEAR(src[kTau], 0.0, 1e-15);  // S^j = 0 at rest
  EXPECT_NEAR(total_pressure(s, g), s.press + 0.5 * B2, 1e-15);
}

}  // namespace
