// RotatingStar's j-constant law and its magnetised differentially rotating star against published
// numbers (the uniform and static magnetised models are in test_published_models.cpp).
//
// 1. A full-GR j-constant model: the Einstein Toolkit's Hydro_RNSID thorn (N. Stergioulas' RNSID, the
//    KEH method in quasi-isotropic coordinates; EinsteinInitialData arrangement, copy read at
//    github.com/marcobrito98/EinsteinInitialData) ships the test `rnsA2` (Hydro_RNSID/test/rnsA2.par,
//    reference output Hydro_RNSID/test/rnsA2/*.asc, written by RNSID on 2017-05-08): K = 100,
//    Gamma = 2, rho_c = 1.07207e-3, r_p/r_e = 0.875, rotation_type = diff with A_diff = A-hat = 1,
//    i.e. the KEH law u^t u_phi = A^2 (Omega_c - Omega) with A = r_e. Its iteration-0 output on the
//    refined level (dx = 1.5) gives rho along x and z, v^y along x (the Eulerian velocity, coordinate
//    component: x (Omega - omega) / alpha, as ours), the lapse and g_xx, g_yy along x. Ours is the
//    xCFC model with A^2 = r_e^2 found by a fixed-point iteration (4 models). The differences are the
//    conformal-flatness error plus RNSID's interpolation onto the Cartesian points: GR's own
//    non-conformally-flat part, g_yy / g_xx - 1, reaches 1.5e-3 on the x axis, and ours lies between
//    g_xx and g_yy. Measured (nr = 400; nr = 800 changes these by < 1e-5): rho within 2.1e-4 rho_c
//    (relative 7.4e-4 at x = 7.5, 2.1e-3 at z = 7.5 where rho = 0.03 rho_c), v^y within 4.1e-4
//    (relative), alpha within 2.7e-5 (inside and out to x = 28.5), psi^4 - g_xx at the centre -9.7e-4
//    (relative). Tolerances: rho 5e-4 rho_c, v^y 1e-3, alpha 1e-4, psi^4 within [g_xx, g_yy] widened
//    by 1.5e-3, the size of GR's anisotropy; with A-hat^2 = 2 instead of 1 the velocity misses by far
//    more (checked below), so the comparison tests the law and its A normalisation.
//
// 2. The paper's magnetized-DRNS (BHAC+ paper, /work/shared/reference/paper.tex, section
//    "Magnetized and differentially rotating star"; the XNS model of Bucciantini & Del Zanna 2011 and
//    Cheong et al. 2021): K = 100, Gamma = 2, rho_c = 1.28e-3, j-constant law with Omega_c = 2.575e-2
//    and A^2 = 70, toroidal field K_m = 3, m = 1. The paper states that the field "reaches a maximum
//    value of ~5e17 G" and puts the stellar surface, where the atmosphere meets the star in its
//    profiles at theta = pi/4 and pi/2, at "r ~ 17 km". One and two printed digits: B_max within
//    [4.5, 5.5]e17 G, the surface radius along theta = pi/2 and pi/4 within [16.5, 17.5] km. Ours:
//    B_max 5.21e17 G, r_e 17.22 km, 17.37 km at pi/4; the same star without its field has r_e = 12.35 km,
//    so the radius tests the field's Bernoulli term. The paper's "~10 % of the total internal energy"
//    names no definition: ours is H/|W| = 0.157, H/(M_proper - M_0) = 0.42, H/M = 0.019 (printed,
//    not asserted).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "EOS/units.hpp"
#include "HydroBase/magnetic_units.hpp"
#include "RotatingStar/rns_solver.hpp"
#include "TOV/cold_slice.hpp"

namespace {
using namespace remnant::rotstar;
constexpr double kHalfPi = 0.5 * std::numbers::pi;

// The rnsA2 reference output at t = 0 on refinement level 1 (x or z = 0, 1.5, ..., 7.5; 1e-11 is
// its atmosphere, reached at 9).
constexpr double kCoord[] = {1.5, 3.0, 4.5, 6.0, 7.5};
constexpr double kRhoX[] = {1.00227640970663e-3, 8.17281799471378e-4, 5.77476781699462e-4, 3.4153381171086e-4,
                            1.4284673071602e-4};
constexpr double kRhoZ[] = {9.8285077363914e-4, 7.58516558077584e-4, 4.86137855371431e-4, 2.33699292717846e-4,
                            3.30338124105266e-5};
constexpr double kVelY[] = {0.0359332020909076, 0.0591499195014883, 0.072536529910777, 0.0809221351209087,
                            0.0861045133059029};
struct LapseRow {
  double x, alpha;
};
constexpr LapseRow kLapse[] = {{0, 0.690992455234209},   {1.5, 0.699983132401919}, {3, 0.724442029515233},
                               {4.5, 0.758114903852241}, {6, 0.794039023232942},   {7.5, 0.826897029349765},
                               {9, 0.853588414420678},   {15, 0.910062481276142},  {28.5, 0.951764604974996}};
struct MetricRow {
  double x, gxx, gyy;
};
constexpr MetricRow kMetric[] = {{0, 1.94255069713767, 1.94255069713767},
                                 {3, 1.80080202407162, 1.80287219467066},
                                 {6, 1.54282536056107, 1.54521040627813},
                                 {15, 1.20188655558788, 1.20230540801015},
                                 {28.5, 1.10252748649696, 1.10263723233236}};

// The j-constant model of the rnsA2 star with A^2 = a_hat2 r_e^2 (r_e its own coordinate radius).
RotatingStarModel rnsid_a2_model(const remnant::tov::ColdSlice& slice, double a_hat2) {
  RnsParameters p;
  p.rho_central = 1.07207e-3;
  p.law = RotationLaw::j_constant;
  p.axis_ratio = 0.875;
  p.nr = 400;
  p.A2 = a_hat2 * 8.9 * 8.9;  // r_e is between the last matter point, 7.5, and 9
  for (int it = 0;; ++it) {
    RotatingStarModel m(slice, p);
    const double A2 = a_hat2 * m.globals().r_e * m.globals().r_e;
    if (std::abs(A2 / p.A2 - 1) < 1e-5 || it == 10) return m;
    p.A2 = A2;
  }
}

TEST(PublishedModels, RnsidDifferentialRotationInFullGr) {
  const auto slice = remnant::tov::polytrope_slice(100.0, 2.0, 0.5);
  const RotatingStarModel m = rnsid_a2_model(*slice, 1.0);
  const RnsGlobals& g = m.globals();
  std::printf("A-hat = 1: A^2 = %.4f (r_e %.5f) Omega_c %.6f Omega_e %.6f M %.6f M_0 %.6f J %.6f\n", m.parameters().A2,
              g.r_e, g.omega_c, g.omega_e, g.M_komar, g.M_rest, g.J);
  EXPECT_NEAR(m.parameters().A2, g.r_e * g.r_e, 1e-3);
  EXPECT_GT(g.r_e, 7.5);
  EXPECT_LT(g.r_e, 9.0);
  const double rho_c = 1.07207e-3;
  double worst_rho = 0, worst_v = 0, worst_alpha = 0;
  for (int k = 0; k < 5; ++k) {
    const double x = kCoord[k];
    const RnsPoint e = m.at(x, kHalfPi), a = m.at(x, 0);
    const double v = e.vel_phi * x;
    std::printf("x = z = %.1f: rho_x %.6e (RNS %.6e) rho_z %.6e (%.6e) v^y %.6f (%.6f, %+.1e)\n", x, e.rho, kRhoX[k], a.rho,
                kRhoZ[k], v, kVelY[k], v / kVelY[k] - 1);
    worst_rho = std::max({worst_rho, std::abs(e.rho - kRhoX[k]) / rho_c, std::abs(a.rho - kRhoZ[k]) / rho_c});
    worst_v = std::max(worst_v, std::abs(v / kVelY[k] - 1));
  }
  for (const LapseRow& r : kLapse) worst_alpha = std::max(worst_alpha, std::abs(m.at(r.x, kHalfPi).alpha - r.alpha));
  std::printf("largest differences: rho %.2e rho_c, v^y %.2e, alpha %.2e\n", worst_rho, worst_v, worst_alpha);
  EXPECT_LT(worst_rho, 5e-4);
  EXPECT_LT(worst_v, 1e-3);
  EXPECT_LT(worst_alpha, 1e-4);
  for (const MetricRow& r : kMetric) {
    const double p4 = std::pow(m.at(r.x, kHalfPi).psi, 4);
    std::printf("x = %4.1f: psi^4 %.6f, GR g_xx %.6f g_yy %.6f\n", r.x, p4, r.gxx, r.gyy);
    EXPECT_GT(p4, r.gxx * (1 - 1.5e-3));
    EXPECT_LT(p4, r.gyy * (1 + 1.5e-3));
  }
  // The comparison sees the law's normalisation: A-hat^2 = 2 (less differential) moves v^y by more
  // than the tolerance.
  const RotatingStarModel n = rnsid_a2_model(*slice, 2.0);
  double miss = 0;
  for (int k = 0; k < 5; ++k) miss = std::max(miss, std::abs(n.at(kCoord[k], kHalfPi).vel_phi * kCoord[k] / kVelY[k] - 1));
  std::printf("A-hat^2 = 2: v^y misses RNSID's by up to %.2e\n", miss);
  EXPECT_GT(miss, 1e-2);
}

TEST(PublishedModels, PaperMagnetizedDrnsFieldAndSurface) {
  const auto slice = remnant::tov::polytrope_slice(100.0, 2.0, 0.5);
  const double km = remnant::units::length_cm * 1e-5;
  auto model = [&](double K_m) {
    RnsParameters p;
    p.law = RotationLaw::j_constant;
    p.omega = 2.575e-2;
    p.A2 = 70;
    p.field.K_m = K_m;
    p.field.m = 1;
    p.nr = 400;  // r_e and B_max within 1e-4 of the default resolution's
    return RotatingStarModel(*slice, p);
  };
  // The surface radius along theta: the outermost matter on the model's ray.
  auto surface = [](const RotatingStarModel& m, double theta) {
    double lo = 0, hi = m.r_out();
    for (int it = 0; it < 60; ++it) (m.at(0.5 * (lo + hi), theta).inside ? lo : hi) = 0.5 * (lo + hi);
    return lo;
  };
  const RotatingStarModel mag = model(3), bare = model(0);
  const RnsGlobals& g = mag.globals();
  const double B_gauss = g.B_max * remnant::hydrobase::kGaussPerCodeB;
  const double r90 = surface(mag, kHalfPi) * km, r45 = surface(mag, 0.25 * std::numbers::pi) * km;
  std::printf("magnetized-DRNS: B_max %.4e G, surface %.3f km (theta = pi/2), %.3f km (pi/4); without the field %.3f km; "
              "H/|W| %.4f, H/(M_proper - M_0) %.4f, H/M %.4f\n",
              B_gauss, r90, r45, bare.globals().r_e * km, g.H_over_W, g.H_mag / (g.M_proper - g.M_rest), g.H_mag / g.M_komar);
  EXPECT_GT(B_gauss, 4.5e17);
  EXPECT_LT(B_gauss, 5.5e17);
  EXPECT_NEAR(r90, 17.0, 0.5);
  EXPECT_NEAR(r45, 17.0, 0.5);
  EXPECT_NEAR(r90, g.r_e * km, 1e-4);  // the ray search vs the solver's surface
  EXPECT_LT(bare.globals().r_e * km, 16.0);  // the radius is the field's doing
}

}  // namespace
