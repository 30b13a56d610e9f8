// The gravitational and geometric sources of the Valencia equations (GRMHD/sources.hpp) checked
// against an independent evaluation of the textbook covariant form
//   s(S_i) = -E d_i alpha + S_k d_i beta^k + (alpha/2) S^jk d_i gamma_jk,
//   s(tau) =  alpha S^ij K_ij - S^j d_j alpha,
// with gamma_jk = psi^4 f_jk, d_i f_jk from finite differences of coords::metric_diagonal (not from
// the Christoffel-derived derivatives the code uses), and K_ij from the CFC shift relation with a
// covariant derivative whose Christoffel symbols are built here from those finite differences.
// Random states with all three velocity components nonzero, random lapse, shift, conformal factor
// and metric derivatives, at random points in Cartesian, cylindrical and spherical coordinates: the
// velocity part of the geometric source (v^theta, v^phi) is invisible to flows along one axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "GRMHD/sources.hpp"
#include "GRMHD/valencia.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;
using Matrix = std::array<std::array<double, 3>, 3>;
// Fourth-order differences: truncation ~h^4 (1e-3 gives 1.7e-8 near the axis), round-off ~1e-16/h.
constexpr double kStep = 1e-4;

// A random point, metric and fluid state.
struct Sample {
  Point3 x{};
  double psi = 1, alpha = 1;
  std::array<double, 3> beta{};
  MetricDerivatives dm;
  double rho = 1, eps = 0, press = 0;
  std::array<double, 3> v{};  // coordinate components v^i
};

// d_i f_jj by fourth-order central differences of coords::metric_diagonal: dfd[i][j].
Matrix metric_derivatives_fd(CoordinateSystem cs, const Point3& x) {
  Matrix d{};
  for (int i = 0; i < 3; ++i) {
    const double h = kStep * std::max(1.0, std::abs(x[i]));
    auto at = [&](double s) {
      Point3 y = x;
      y[i] += s * h;
      return coords::metric_diagonal(cs, y);
    };
    const Point3 m2 = at(-2), m1 = at(-1), p1 = at(1), p2 = at(2);
    for (int j = 0; j < 3; ++j) d[i][j] = (m2[j] - 8.0 * m1[j] + 8.0 * p1[j] - p2[j]) / (12.0 * h);
  }
  return d;
}

// d_i ln sqrt(f) by fourth-order central differences of coords::sqrt_det_metric.
Point3 log_sqrt_f_derivative_fd(CoordinateSystem cs, const Point3& x) {
  Point3 d{};
  for (int i = 0; i < 3; ++i) {
    const double h = kStep * std::max(1.0, std::abs(x[i]));
    auto at = [&](double s) {
      Point3 y = x;
      y[i] += s * h;
      return std::log(coords::sqrt_det_metric(cs, y));
    };
    d[i] = (at(-2) - 8.0 * at(-1) + 8.0 * at(1) - at(2)) / (12.0 * h);
  }
  return d;
}

// Gamma^a_bc = (1/2) f^ad (d_b f_dc + d_c f_db - d_d f_bc) for diagonal f, from the differences.
Christoffels christoffels_fd(const Point3& f, const Matrix& dfd) {
  Christoffels g{};
  auto df = [&](int i, int j, int k) { return j == k ? dfd[i][j] : 0.0; };  // d_i f_jk
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c) g[a][b][c] = 0.5 / f[a] * (df(b, a, c) + df(c, a, b) - df(a, b, c));
  return g;
}

// The reference: sources in covariant form, momentum sources including the pressure part.
struct Reference {
  std::array<double, 3> s{};  // s(S_i)
  double tau = 0;
  double scale = 0;  // sum of the magnitudes of the terms, the scale of the round-off
};

Reference covariant_sources(CoordinateSystem cs, const Sample& q) {
  const Point3 f = coords::metric_diagonal(cs, q.x);
  const Matrix dfd = metric_derivatives_fd(cs, q.x);
  const Christoffels gam = christoffels_fd(f, dfd);
  const double psi4 = std::pow(q.psi, 4), psi3 = std::pow(q.psi, 3);
  Matrix g_dn{}, g_up{};  // gamma_jk, gamma^jk
  for (int j = 0; j < 3; ++j) {
    g_dn[j][j] = psi4 * f[j];
    g_up[j][j] = 1.0 / g_dn[j][j];
  }
  double v2 = 0;
  for (int j = 0; j < 3; ++j) v2 += g_dn[j][j] * q.v[j] * q.v[j];
  const double W2 = 1.0 / (1.0 - v2);
  const double h = 1.0 + q.eps + q.press / q.rho;
  const double z = q.rho * h * W2;
  const double E = z - q.press;
  std::array<double, 3> S_dn{}, S_up{};
  Matrix S_uu{};  // S^jk
  for (int j = 0; j < 3; ++j) {
    S_up[j] = z * q.v[j];
    S_dn[j] = z * g_dn[j][j] * q.v[j];
    for (int k = 0; k < 3; ++k) S_uu[j][k] = z * q.v[j] * q.v[k] + q.press * g_up[j][k];
  }
  Reference r;
  for (int i = 0; i < 3; ++i) {
    double si = -E * q.dm.dalpha[i];
    r.scale += std::abs(si);
    for (int k = 0; k < 3; ++k) {
      si += S_dn[k] * q.dm.dbeta[i][k];
      r.scale += std::abs(S_dn[k] * q.dm.dbeta[i][k]);
    }
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const double fjk = j == k ? f[j] : 0.0, dfjk = j == k ? dfd[i][j] : 0.0;
        const double dgamma = 4.0 * psi3 * q.dm.dpsi[i] * fjk + psi4 * dfjk;
        si += 0.5 * q.alpha * S_uu[j][k] * dgamma;
        r.scale += std::abs(0.5 * q.alpha * S_uu[j][k] * dgamma);
      }
    r.s[i] = si;
  }
  // K^ij = (nabla^i beta^j + nabla^j beta^i - (2/3) f^ij nabla_k beta^k) / (2 alpha psi^4).
  Matrix nb{};  // nabla_i beta^j
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      nb[i][j] = q.dm.dbeta[i][j];
      for (int k = 0; k < 3; ++k) nb[i][j] += gam[j][i][k] * q.beta[k];
    }
  const double div = nb[0][0] + nb[1][1] + nb[2][2];
  double tau = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double Kup = (nb[i][j] / f[i] + nb[j][i] / f[j] - (i == j ? 2.0 / 3.0 * div / f[i] : 0.0)) / (2.0 * q.alpha * psi4);
      const double Kdn = g_dn[i][i] * g_dn[j][j] * Kup;
      tau += q.alpha * S_uu[i][j] * Kdn;
      r.scale += std::abs(q.alpha * S_uu[i][j] * Kdn);
    }
  for (int j = 0; j < 3; ++j) {
    tau -= S_up[j] * q.dm.dalpha[j];
    r.scale += std::abs(S_up[j] * q.dm.dalpha[j]);
  }
  r.tau = tau;
  return r;
}

// The code's sources, called the way the GRMHD right-hand side calls them (src/rhs.cpp), plus the
// pressure part alpha p d_i ln sqrt(f) that the right-hand side adds as an exact cell average.
std::array<double, kNumCons> code_sources(CoordinateSystem cs, const Sample& q, bool shift) {
  const bool cartesian = cs == CoordinateSystem::cartesian;
  const bool spherical = cs == CoordinateSystem::spherical;
  const double sin_t = spherical ? std::sin(q.x[1]) : 0.0, cos_t = spherical ? std::cos(q.x[1]) : 0.0;
  Point3 fd{1.0, 1.0, 1.0};
  Christoffels gam{};
  std::array<std::array<double, 3>, 3> df{};
  if (!cartesian) {
    fd = coords::metric_diagonal(cs, q.x, sin_t);
    gam = coords::christoffels(cs, q.x, sin_t, cos_t);
    df = metric_diagonal_derivatives(fd, gam);
  }
  const PointMetric pm = cartesian ? point_metric_cartesian(q.psi, q.alpha, q.beta) : point_metric(q.psi, q.alpha, q.beta, fd);
  FluidState fs;
  fs.rho = q.rho;
  fs.press = q.press;
  fs.eps = q.eps;
  fs.h = 1.0 + fs.eps + fs.press / fs.rho;
  for (int c = 0; c < 3; ++c) {
    fs.v[c] = q.v[c];
    fs.v_dn[c] = pm.g_dn[c] * fs.v[c];
  }
  fs.v2 = fs.v[0] * fs.v_dn[0] + fs.v[1] * fs.v_dn[1] + fs.v[2] * fs.v_dn[2];
  fs.W = 1.0 / std::sqrt(1.0 - fs.v2);
  std::array<double, kNumCons> src{};
  gravity_sources(fs, pm, q.psi, q.dm, df, cartesian ? nullptr : &gam, shift, src.data());
  const Point3 dlnf = log_sqrt_f_derivative_fd(cs, q.x);
  for (int d = 0; d < 3; ++d) src[kS1 + d] += q.alpha * fs.press * dlnf[d];
  return src;
}

Sample random_sample(CoordinateSystem cs, std::mt19937_64& rng, bool shift) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto in = [&](double a, double b) { return a + (b - a) * u(rng); };
  Sample q;
  constexpr double pi = std::numbers::pi;
  switch (cs) {
    case CoordinateSystem::cartesian: q.x = {in(-2, 2), in(-2, 2), in(-2, 2)}; break;
    case CoordinateSystem::cylindrical: q.x = {in(0.2, 3), in(-2, 2), in(0, 2 * pi)}; break;
    case CoordinateSystem::spherical: q.x = {in(0.2, 3), in(0.15, pi - 0.15), in(0, 2 * pi)}; break;
  }
  q.psi = in(0.8, 1.6);
  q.alpha = in(0.4, 1.0);
  for (int i = 0; i < 3; ++i) {
    q.dm.dpsi[i] = in(-1, 1);
    q.dm.dalpha[i] = in(-1, 1);
    if (shift) {
      q.beta[i] = in(-0.3, 0.3);
      for (int k = 0; k < 3; ++k) q.dm.dbeta[i][k] = in(-1, 1);
    }
  }
  q.rho = in(0.05, 2.0);
  q.eps = in(0.01, 1.0);
  q.press = (5.0 / 3.0 - 1.0) * q.rho * q.eps * in(0.5, 1.5);  // any positive pressure
  // Orthonormal-frame speeds, all three nonzero, |v| < 0.9, mapped to coordinate components.
  const Point3 f = coords::metric_diagonal(cs, q.x);
  const double psi2 = q.psi * q.psi;
  std::array<double, 3> vhat{};
  do {
    for (int i = 0; i < 3; ++i) vhat[i] = in(-0.55, 0.55);
  } while (vhat[0] * vhat[0] + vhat[1] * vhat[1] + vhat[2] * vhat[2] > 0.81 ||
           std::min({std::abs(vhat[0]), std::abs(vhat[1]), std::abs(vhat[2])}) < 0.05);
  for (int i = 0; i < 3; ++i) q.v[i] = vhat[i] / (psi2 * std::sqrt(f[i]));
  return q;
}

// Largest difference relative to the scale of the terms over many random samples.
double max_relative_difference(CoordinateSystem cs, bool shift, unsigned seed) {
  std::mt19937_64 rng(seed);
  double worst = 0;
  for (int n = 0; n < 500; ++n) {
    const Sample q = random_sample(cs, rng, shift);
    const Reference r = covariant_sources(cs, q);
    const auto c = code_sources(cs, q, shift);
    EXPECT_EQ(c[kD], 0.0);
    EXPECT_EQ(c[kDYe], 0.0);
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(c[kS1 + i] - r.s[i]) / r.scale);
    worst = std::max(worst, std::abs(c[kTau] - r.tau) / r.scale);
  }
  std::printf("%s, shift %s: max |code - covariant| / scale = %.3e\n", to_string(cs), shift ? "on" : "off", worst);
  return worst;
}

constexpr double kTolerance = 1e-10;

TEST(GravitySources, MatchCovariantFormCartesian) {
  EXPECT_LT(max_relative_difference(CoordinateSystem::cartesian, true, 11), kTolerance);
  EXPECT_LT(max_relative_difference(CoordinateSystem::cartesian, false, 12), kTolerance);
}

TEST(GravitySources, MatchCovariantFormCylindrical) {
  EXPECT_LT(max_relative_difference(CoordinateSystem::cylindrical, true, 21), kTolerance);
  EXPECT_LT(max_relative_difference(CoordinateSystem::cylindrical, false, 22), kTolerance);
}

TEST(GravitySources, MatchCovariantFormSpherical) {
  EXPECT_LT(max_relative_difference(CoordinateSystem::spherical, true, 31), kTolerance);
  EXPECT_LT(max_relative_difference(CoordinateSystem::spherical, false, 32), kTolerance);
}

// The Christoffel symbols the code's covariant derivative and df use agree with those built here
// from finite differences of the reference metric.
TEST(GravitySources, ChristoffelsMatchMetricDifferences) {
  std::mt19937_64 rng(41);
  for (CoordinateSystem cs : {CoordinateSystem::cylindrical, CoordinateSystem::spherical})
    for (int n = 0; n < 100; ++n) {
      const Point3 x = random_sample(cs, rng, false).x;
      const Christoffels a = coords::christoffels(cs, x);
      const Christoffels b = christoffels_fd(coords::metric_diagonal(cs, x), metric_derivatives_fd(cs, x));
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[i][j][k], b[i][j][k], 1e-9 * (1.0 + std::abs(b[i][j][k]))) << to_string(cs);
    }
}

}  // namespace
