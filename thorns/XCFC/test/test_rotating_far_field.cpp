// The far field of a slowly, rigidly rotating star from the xCFC solver (issue 20, item 3):
//   psi -> 1 + M / 2r with M = int (E~ / psi + A_ij A^ij / (16 pi psi^7)) dV (the CFC ADM mass);
//   beta^phi -> -2 J / r^3 with J = int S~_phi dV, the star's angular momentum, here in closed form.
// Outside the star the shift equation still has the source 2 A^ij d_j(alpha psi^-6): the flux of
// (L beta)^ij phi_i through a sphere is 2 int alpha psi^-6 A^ij phi_i dS_j = 16 pi J alpha psi^-6,
// so the l = 1 part of beta^phi is b(r) = -6 J int_r^inf alpha psi^-6 r'^-4 dr', with the exterior
// psi = 1 + M / 2r and alpha psi = 1 - M' / 2r (= -2 J / r^3 (1 - 3M / r) to first order). The
// l = 1 part of beta^phi is its sin^3(theta)-weighted mean over theta (orthogonal to l = 3).
// A wrong coupling constant in the shift source (16 pi) or a missing A^ij d_j(alpha psi^-6) term
// moves b(r) by 100 % or by 3M/r (3 % here); the test asks for 0.5 %. The outer boundary lies far
// out (r = 256, 13 extraction radii) so that the vector far-field conditions leave no floor.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "XCFC/xcfc_system.hpp"
#include "manufactured.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;
constexpr double pi = std::numbers::pi;

// E~ = rho0 (1 - r^2/R^2)^2 inside R, S~_phi = Omega varpi^2 E~ (rigid rotation, h W^2 ~ 1),
// S~ = 0. Closed forms: int E~ dV = 4 pi rho0 R^3 8/105, J = (8 pi / 3) Omega rho0 R^5 8/315.
struct Star {
  double R = 5, M0 = 0.2, Omega = 0.02;
  double rho0() const { return M0 * 105 / (32 * pi * R * R * R); }
  double J() const { return 8 * pi / 3 * Omega * rho0() * std::pow(R, 5) * 8 / 315; }
  double E(double r) const { return r < R ? rho0() * std::pow(1 - r * r / (R * R), 2) : 0.0; }
};

struct FarField {
  double M_psi_far, M_psi_src;   // 2 r (<psi> - 1) at the extraction radius; the volume integral
  double M_ap_far, M_ap_src;     // -2 r (<alpha psi> - 1); (1 / 2 pi) int alpha psi k dV
  double b_far, b_pred;          // l = 1 part of beta^phi; the prediction above
};

double cell_volume(const GridShape& s, int i, int j) {
  return coords::volume_factor_integral(s.coordinates, 0, s.face(0, i), s.face(0, i + 1)) *
         coords::volume_factor_integral(s.coordinates, 1, s.face(1, j), s.face(1, j + 1)) * 2 * pi * 2;  // times 2: the mirror half below the equator
}

FarField solve_star(const Star& star, const GridShape& s, double r_ext) {
  XcfcSolver solver(s);
  CompositeMultigrid& mg = solver.multigrid();
  CompositeField E = mg.field(), Str = mg.field();
  VectorField S;
  for (auto& c : S) c = mg.field();
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const Point3 x = s.point(i, j, k);
    const double varpi = x[0] * std::sin(x[1]);
    E.part[0][q] = star.E(x[0]);
    S[2].part[0][q] = star.Omega * varpi * varpi * E.part[0][q];
  });
  XcfcState st;
  XcfcStats stats;
  SolveSettings set;
  set.tolerance = 1e-12;
  set.full_multigrid = true;
  solver.solve_conformal_factor(E, S, st, stats, set);
  solver.solve_lapse_and_shift(E, S, Str, st, stats, set);
  EXPECT_TRUE(stats.X.converged() && stats.psi.converged && stats.alpha_psi.converged && stats.beta.converged());

  FarField f{};
  // Volume integrals (second-order quadrature over the cells).
  for_cells(s, [&](std::size_t q, int i, int j, int) {
    const double dV = cell_volume(s, i, j), psi = st.psi.part[0][q], A2 = st.A2.part[0][q];
    const double ap = st.alpha_psi.part[0][q];
    f.M_psi_src += (E.part[0][q] / psi + A2 / (16 * pi * std::pow(psi, 7))) * dV;
    f.M_ap_src += ap * (E.part[0][q] / (psi * psi) + 0.875 * A2 / (2 * pi * std::pow(psi, 8))) * dV;
  });
  // Angular means on the two radial cells around r_ext, interpolated linearly to r_ext.
  auto mean_at = [&](int i, auto value, auto weight) {
    double sum = 0, wsum = 0;
    for (int j = 0; j < s.n[1]; ++j) {
      const std::size_t q = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * s.n[0];
      const double w = weight(s.point(i, j, 0)[1]);
      sum += w * value(q), wsum += w;
    }
    return sum / wsum;
  };
  const int i0 = static_cast<int>(std::floor((r_ext - s.lo[0]) / s.dx[0] - 0.5));
  const double r0 = s.centre(0, i0), t = (r_ext - r0) / s.dx[0];
  auto radial = [&](auto value, auto weight) { return (1 - t) * mean_at(i0, value, weight) + t * mean_at(i0 + 1, value, weight); };
  auto sin1 = [](double th) { return std::sin(th); };
  auto sin3 = [](double th) { return std::pow(std::sin(th), 3); };
  f.M_psi_far = 2 * r_ext * (radial([&](std::size_t q) { return st.psi.part[0][q]; }, sin1) - 1);
  f.M_ap_far = -2 * r_ext * (radial([&](std::size_t q) { return st.alpha_psi.part[0][q]; }, sin1) - 1);
  f.b_far = radial([&](std::size_t q) { return st.beta[2].part[0][q]; }, sin3);
  // b(r) = -6 J int_0^{1/r} w(1/u) u^2 du (u = 1/r'), Simpson.
  const int n = 400;
  const double h = 1 / (r_ext * n);
  double integral = 0;
  for (int m = 0; m <= n; ++m) {
    const double u = m * h;
    const double w = (1 - f.M_ap_far * u / 2) / std::pow(1 + f.M_psi_far * u / 2, 7);
    integral += (m == 0 || m == n ? 1 : (m % 2 ? 4 : 2)) * w * u * u;
  }
  f.b_pred = -6 * star.J() * integral * h / 3;
  return f;
}

}  // namespace

TEST(XCFCMomentumCoupling, SlowlyRotatingStarFarField) {
  using B = Boundary;
  const Star star;
  const GridShape base = make_shape(CoordinateSystem::spherical, 2, {256, 4, 1}, {0, 0, 0}, {256, pi / 2, 2 * pi},
                                    {{{B::origin, B::outer}, {B::axis, B::reflect}, {B::outer, B::outer}}});
  const double r_ext = 20;
  FarField f[3];
  double err_psi[3], err_ap[3], err_b[3];
  for (int m = 0; m < 3; ++m) {
    f[m] = solve_star(star, scaled(base, 1 << m), r_ext);
    err_psi[m] = std::abs(f[m].M_psi_far / f[m].M_psi_src - 1);
    err_ap[m] = std::abs(f[m].M_ap_far / f[m].M_ap_src - 1);
    err_b[m] = std::abs(f[m].b_far / f[m].b_pred - 1);
    std::printf("rotating star r=%g  M(psi) far %.6f src %.6f | M(alpha psi) far %.6f src %.6f | r^3 b far %.6f pred %.6f "
                "(-2J = %.6f)\n",
                r_ext, f[m].M_psi_far, f[m].M_psi_src, f[m].M_ap_far, f[m].M_ap_src, f[m].b_far * std::pow(r_ext, 3),
                f[m].b_pred * std::pow(r_ext, 3), -2 * star.J());
  }
  std::printf("relative errors: M(psi) %.2e %.2e %.2e  M(alpha psi) %.2e %.2e %.2e  beta^phi %.2e %.2e %.2e\n", err_psi[0],
              err_psi[1], err_psi[2], err_ap[0], err_ap[1], err_ap[2], err_b[0], err_b[1], err_b[2]);
  // Measured (r_max = 256, dr = 1, 0.5, 0.25): M(psi) and M(alpha psi) 4.2e-4, 1.0e-4, 2.6e-5 (order
  // 2.00); beta^phi 3.1e-2, 6.3e-3, 1.65e-3 (order 2.3, 1.9). Bounds: 4x the finest error, order 1.7
  // (beta: 1.5, its outer-boundary floor ~1e-4 starts to show).
  EXPECT_LT(err_psi[2], 1e-4);
  EXPECT_LT(err_ap[2], 1e-4);
  EXPECT_LT(err_b[2], 5e-3);
  EXPECT_GT(order(err_psi[1], err_psi[2]), 1.7);
  EXPECT_GT(order(err_ap[1], err_ap[2]), 1.7);
  EXPECT_GT(order(err_b[1], err_b[2]), 1.5);
}
