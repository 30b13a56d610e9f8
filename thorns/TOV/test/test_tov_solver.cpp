// TOV solver: the BU0 model (K = 100, Gamma = 2, rho_c = 1.28e-3) against published values
// (Font et al. 2002, PRD 65, 084024: M = 1.400, M0 = 1.506, R = 9.586 areal), and convergence
// of the mass with the number of samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "TOV/tov_solver.hpp"

namespace {
using namespace remnant::tov;

TEST(TovSolver, BU0Model) {
  const auto slice = polytrope_slice(100.0, 2.0, 0.5);
  const TovStar star(*slice, 1.28e-3);
  std::printf("BU0: M = %.6f, M0 = %.6f, R = %.5f, Rbar = %.5f\n", star.gravitational_mass(), star.rest_mass(),
              star.areal_radius(), star.isotropic_radius());
  EXPECT_NEAR(star.gravitational_mass(), 1.400, 1e-3);
  EXPECT_NEAR(star.rest_mass(), 1.506, 1e-3);
  EXPECT_NEAR(star.areal_radius(), 9.586, 5e-3);
  // Continuity at the surface and the centre's values.
  const TovPoint in = star.at(star.isotropic_radius() * (1 - 1e-9)), out = star.at(star.isotropic_radius() * (1 + 1e-9));
  EXPECT_NEAR(in.psi, out.psi, 1e-6);
  EXPECT_NEAR(in.alpha, out.alpha, 1e-6);
  EXPECT_NEAR(star.at(0).rho, 1.28e-3, 1e-12);
}

TEST(TovSolver, SamplesConverge) {
  const auto slice = polytrope_slice(100.0, 2.0, 0.5);
  const TovStar a(*slice, 1.28e-3, 500), b(*slice, 1.28e-3, 4000);
  EXPECT_NEAR(a.gravitational_mass(), b.gravitational_mass(), 1e-8);
  EXPECT_NEAR(a.at(3.0).psi, b.at(3.0).psi, 1e-6);
}

TEST(TovSolver, TabulatedSliceOfAPolytropeAgrees) {
  std::vector<double> rho, p, eps, ye;
  for (int i = 0; i < 2000; ++i) {
    const double r = 1e-12 * std::pow(1e10, i / 1999.0);
    rho.push_back(r);
    p.push_back(100 * r * r);
    eps.push_back(100 * r);
    ye.push_back(0.1);
  }
  const auto tab = tabulated_slice(rho, p, eps, ye);
  const auto poly = polytrope_slice(100.0, 2.0, 0.1);
  const TovStar a(*tab, 1.28e-3), b(*poly, 1.28e-3);
  EXPECT_NEAR(a.gravitational_mass(), b.gravitational_mass(), 2e-4);  // trapezoidal H(rho)
  EXPECT_NEAR(a.areal_radius(), b.areal_radius(), 1e-2);
}

}  // namespace

namespace {

// A polytrope sampled on n log-spaced densities, split into 5 segments at a point of a kink-free
// EOS: H(rho) of the segmented slice (quadratics inside each segment) against the closed form.
double segmented_enthalpy_error(int n) {
  using namespace remnant::tov;
  std::vector<double> rho, p, eps, ye;
  std::vector<std::size_t> starts;
  for (int i = 0; i <= n; ++i) {
    if (i % (n / 5) == 0 && i < n) starts.push_back(rho.size());
    const double r = 1e-8 * std::pow(1e6, double(i) / n);
    rho.push_back(r), p.push_back(100 * r * r), eps.push_back(100 * r), ye.push_back(0.1);
  }
  const auto tab = tabulated_slice_segments(rho, p, eps, ye, starts);
  const auto poly = polytrope_slice(100.0, 2.0, 0.1);
  const double H0 = poly->log_enthalpy(1e-8);  // the slice starts at H = 0 there
  double err = 0;
  for (double r : {3e-6, 1e-4, 1e-3, 5e-3}) err = std::max(err, std::abs(tab->log_enthalpy(r) - (poly->log_enthalpy(r) - H0)));
  return err;
}

TEST(TovSolver, SegmentedSliceIntegratesTheEnthalpyAtThirdOrder) {
  const double e1 = segmented_enthalpy_error(100), e2 = segmented_enthalpy_error(200);
  std::printf("segmented slice: |H - H_exact| %.3e %.3e (order %.2f)\n", e1, e2, std::log2(e1 / e2));
  EXPECT_GT(std::log2(e1 / e2), 2.6);  // the trapezoidal rule is second order
}

}  // namespace
