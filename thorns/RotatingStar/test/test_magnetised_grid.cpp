// The paper's magnetized-DRNS parfile (RotatingStar with K_m = 3, m = 1; SeedMagneticField writes
// the same toroidal law onto the phi faces, or through a vector potential on 3D Cartesian grids): at t = 0 Analysis's magnetic energy, B_max, J and rest
// mass match the model's, div B is zero; evolved, it stays at rest where the unmagnetised model
// with the same field does not; RotatingStar_CheckParameters refuses a magnetised
// equilibrium whose field the run would not evolve or would seed with another law.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "HydroBase/magnetic_units.hpp"
#include "RotatingStar/rns_solver.hpp"
#include "TOV/cold_slice.hpp"
#include "parfile_run.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/driver.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

remnant::analysis::StarDiagnostics start(const std::string& parfile, std::vector<std::string> extra = {}) {
  return remnant::rotstar::test::initial_diagnostics(parfile, "rotmag", std::move(extra));
}

std::string error_of(const std::string& parfile, std::vector<std::string> extra) {
  try {
    start(parfile, std::move(extra));
  } catch (const std::exception& e) {
    std::printf("%s\n", e.what());
    return e.what();
  }
  return "no error";
}

// The parfile covers theta in [0, pi/2] (a reflect equator): Analysis integrates over the grid, so
// the whole star's E_mag, J, M_0 and M_komar are twice the grid's. Measured with the paper's core
// layout (dr = 0.78 for r < 6.25, where B peaks): E_mag -6.9e-3, B_max -1.5e-2, J +4.0e-4,
// M_0 -2.4e-3, M_komar -2.6e-3, T/|W| +5.0e-3 (with the finest level down to r = 0, dr = 0.39:
// -2.5e-3, -2.3e-3, -3.5e-4, -9.1e-4, -9.0e-4, +1.8e-3): the grid's discretisation; div B = 0.
TEST(MagnetisedDrns, ParfileStartsWithTheModelsField) {
  const auto slice = remnant::tov::polytrope_slice(100.0, 2.0, 0.5);
  remnant::rotstar::RnsParameters p = remnant::rotstar::test::drns_parameters();
  p.field.K_m = 3;
  p.field.m = 1;
  const remnant::rotstar::RotatingStarModel model(*slice, p);
  const auto& g = model.globals();
  const auto row = start("magnetized_drns.yaml");
  ASSERT_TRUE(row.magnetic.has_value());
  const auto& mag = *row.magnetic;
  const double mirror = 2;  // the equatorial reflect boundary
  const double B_max_model = g.B_max * remnant::hydrobase::kGaussPerCodeB;
  std::printf("magnetized_drns at t = 0 (whole star): E_mag %.7f (model H %.7f), B_max %.5e G (%.5e), J %.6f (%.6f), M_0 %.6f (%.6f), "
              "divB_max %.2e, E_mag_pol %.2e, M_komar %.6f (%.6f), T/|W| %.6f (%.6f)\n",
              mirror * mag.E_mag, g.H_mag, mag.B_max_gauss, B_max_model, mirror * row.rotation.J, g.J, mirror * row.rest_mass, g.M_rest,
              mag.divB_max, mag.E_mag_pol, mirror * row.rotation.M_komar, g.M_komar, row.rotation.T_over_W, g.T_over_W);
  EXPECT_NEAR(mirror * mag.E_mag / g.H_mag, 1, 1e-2);
  EXPECT_NEAR(mag.B_max_gauss / B_max_model, 1, 2.5e-2);
  EXPECT_NEAR(mirror * row.rotation.J / g.J, 1, 1e-3);
  EXPECT_NEAR(mirror * row.rest_mass / g.M_rest, 1, 4e-3);
  EXPECT_LT(mag.divB_max, 1e-12);
  EXPECT_EQ(mag.E_mag_pol, 0.0);
  // Analysis's Komar mass with the field's stress (-1.6 % without it) and T/|W| with E_mag in |W| (+3.8 % without).
  EXPECT_NEAR(mirror * row.rotation.M_komar / g.M_komar, 1, 4e-3);
  EXPECT_NEAR(row.rotation.T_over_W / g.T_over_W, 1, 1e-2);
}

// 3D Cartesian grids (the whole star, no mirror: the toroidal field is odd under the equatorial
// one): SeedMagneticField's vector potential A_z(varpi, z) gives div B at round-off; the magnetic
// energy converges to the model's H (measured -10.1 % at dx = 1, -4.7 % at dx = 0.625: order 1.6,
// the potential's (varpi, z) bins), the poloidal leak is 2e-4 of E_mag.
TEST(MagnetisedDrns, CartesianFieldFromTheVectorPotential) {
  const double H = 0.0284212;  // the model's (RotatingStar log, nr = 800)
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const int n = k == 0 ? 32 : 48;
    const std::string x = k == 0 ? "16" : "15";
    const auto row = start("magnetized_drns.yaml",
                           {"Grid::coordinates=cartesian", "Grid::dimension=3", "Grid::ncells=[" + std::to_string(n) + "," + std::to_string(n) + "," + std::to_string(n) + "]",
                            "Grid::block_size=[16,16,16]", "Grid::xmin=[-" + x + ",-" + x + ",-" + x + "]", "Grid::xmax=[" + x + "," + x + "," + x + "]",
                            "Grid::boundary_lower=[outflow,outflow,outflow]", "Grid::boundary_upper=[outflow,outflow,outflow]",
                            "Grid::max_level=0", "Grid::regions=[]", "Grid::region_levels=[]", "Grid::region_modes=[]", "Grid::region_bounds=[]",
                            "Grid::axial_vector_reflection=[mirror,mirror,mirror]"});
    const auto& mag = *row.magnetic;
    err[k] = mag.E_mag / H - 1;
    std::printf("3D Cartesian dx = %.3f: E_mag %.6f (H %.6f, %+.2e), E_mag_pol %.2e, divB_max %.2e, B_max %.4e G\n",
                2 * std::stod(x) / n, mag.E_mag, H, err[k], mag.E_mag_pol, mag.divB_max, mag.B_max_gauss);
    EXPECT_LT(mag.divB_max, 1e-12);
    EXPECT_LT(mag.E_mag_pol, 1e-3 * mag.E_mag);
    EXPECT_LT(std::abs(err[k]), 0.12);
  }
  EXPECT_GT(std::abs(err[0] / err[1]), 1.8);  // dx ratio 1.6
}

// 2D cylindrical grids (R in [0, 16], z in [-16, 16]): psi^6 B^phi on the phi faces, div B = 0;
// E_mag converges to H at second order (measured -5.3e-3, -1.3e-3 at dx = 0.5, 0.25), M_komar
// -1.4e-3, -3.0e-4.
TEST(MagnetisedDrns, CylindricalPhiFaces) {
  const double H = 0.0284212, M = 1.475019;  // the model's
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const int n = 32 << k;
    const auto row = start("magnetized_drns.yaml",
                           {"Grid::coordinates=cylindrical", "Grid::dimension=2", "Grid::ncells=[" + std::to_string(n) + "," + std::to_string(2 * n) + ",1]",
                            "Grid::block_size=[16,16,1]", "Grid::xmin=[0,-16,0]", "Grid::xmax=[16,16,6.283185307179586]",
                            "Grid::boundary_lower=[axis,outflow,outflow]", "Grid::boundary_upper=[outflow,outflow,outflow]",
                            "Grid::max_level=0", "Grid::regions=[]", "Grid::region_levels=[]", "Grid::region_modes=[]", "Grid::region_bounds=[]",
                            "Grid::axial_vector_reflection=[mirror,mirror,mirror]"});
    const auto& mag = *row.magnetic;
    err[k] = mag.E_mag / H - 1;
    std::printf("2D cylindrical dx = %.3f: E_mag %.6f (%+.2e), M_komar %.6f (%+.2e), divB_max %.2e\n", 16.0 / n, mag.E_mag, err[k],
                row.rotation.M_komar, row.rotation.M_komar / M - 1, mag.divB_max);
    EXPECT_LT(mag.divB_max, 1e-12);
    EXPECT_EQ(mag.E_mag_pol, 0.0);
    EXPECT_NEAR(row.rotation.M_komar / M, 1, 2e-3);
  }
  EXPECT_GT(std::log2(err[0] / err[1]), 1.8);
}

// parfiles/magnetized_drns_cyl_2d.yaml, the one-core variant of the paper's test (2D cylindrical,
// three levels to dx = 0.25, dt = 0.44 instead of 3.2e-3): at t = 0 the model's field and star.
// Measured: E_mag -1.4e-3, B_max -2.6e-3, J -4e-7, M_0 -2.7e-4 (100 steps, 0.22 ms: rho_c 3e-4,
// E_mag 6.8e-4, J 5e-7, divB_max 0).
TEST(MagnetisedDrns, CylindricalVariantStartsWithTheModel) {
  const auto slice = remnant::tov::polytrope_slice(100.0, 2.0, 0.5);
  remnant::rotstar::RnsParameters p = remnant::rotstar::test::drns_parameters();
  p.field.K_m = 3;
  p.field.m = 1;
  p.nr = 400;
  const remnant::rotstar::RotatingStarModel model(*slice, p);
  const auto& g = model.globals();
  const auto row = start("magnetized_drns_cyl_2d.yaml", {"RotatingStar::nr=400"});
  ASSERT_TRUE(row.magnetic.has_value());
  const auto& mag = *row.magnetic;
  const double B_max_model = g.B_max * remnant::hydrobase::kGaussPerCodeB;
  std::printf("magnetized_drns_cyl_2d at t = 0: E_mag %+.2e, B_max %+.2e, J %+.2e, M_0 %+.2e, divB_max %.1e\n", mag.E_mag / g.H_mag - 1,
              mag.B_max_gauss / B_max_model - 1, row.rotation.J / g.J - 1, row.rest_mass / g.M_rest - 1, mag.divB_max);
  EXPECT_NEAR(mag.E_mag / g.H_mag, 1, 3e-3);
  EXPECT_NEAR(mag.B_max_gauss / B_max_model, 1, 5e-3);
  EXPECT_NEAR(row.rotation.J / g.J, 1, 1e-3);
  EXPECT_NEAR(row.rest_mass / g.M_rest, 1, 1e-3);
  EXPECT_LT(mag.divB_max, 1e-12);
}

// The largest poloidal (meridional) speed sqrt(gamma_11 v1^2 + gamma_22 v2^2) where rho > 1e-2 rho_max
// after `steps` steps of magnetized_drns.yaml on its base level only (dr = 1.56; one rank).
double poloidal_speed_after(int steps, std::vector<std::string> extra) {
  extra.insert(extra.begin(), {"MoL::max_iterations=" + std::to_string(steps), "MoL::final_time=-1", "IO::hdf5_every_time=0",
                               "Analysis::every=0", "Grid::max_level=0", "Grid::regions=[]", "Grid::region_levels=[]",
                               "Grid::region_modes=[]", "Grid::region_bounds=[]", "RotatingStar::nr=400"});
  remnant::rotstar::test::ParfileRun sim("magnetized_drns.yaml", "rotmag_v", extra);
  auto& ctx = sim.context();
  double rho_max = 0, speed = 0;
  for (int pass = 0; pass < 2; ++pass)
    for (remnant::Block* b : ctx.grid().local_blocks()) {
      const remnant::vars::HydroBase::prim prim(ctx, *b);
      const remnant::vars::Spacetime::metric metric(ctx, *b);
      remnant::for_interior(*b, [&](int i, int j, int k) {
        if (pass == 0) return void(rho_max = std::max(rho_max, prim.rho(i, j, k)));
        if (prim.rho(i, j, k) < 1e-2 * rho_max) return;
        const remnant::Point3 f = remnant::coords::metric_diagonal(b->coordinates, remnant::cell_point(*b, i, j, k));
        const double psi4 = std::pow(metric.psi(i, j, k), 4), v1 = prim.vel(0, i, j, k), v2 = prim.vel(1, i, j, k);
        speed = std::max(speed, std::sqrt(psi4 * (f[0] * v1 * v1 + f[1] * v2 * v2)));
      });
    }
  return speed;
}

// The equilibrium matters: the same field on the unmagnetised model (RotatingStar::K_m = 0, the
// Lorentz force unbalanced) drives meridional flows that do not go away with resolution, while the
// magnetised equilibrium's residual flow is discretisation error and converges. After 40 steps
// (t = 2) at dr = 1.56: 1.35e-2 vs 5.26e-2; at dr = 0.78 (80 steps, same t): 3.94e-3 (ratio 3.4,
// order 1.8) vs 3.71e-2.
// History: the rotmag branch measured 6.4e-3 vs 5.0e-2 at dr = 1.56 with bounds < 1e-2 and
// < 0.25 x unbalanced. mhd-core 8c7229d (reconstruction of the orthonormal transverse field
// r sin(theta) B^phi instead of B^phi in the sweeps: 6.4e-3 -> 7.9e-3 alone; the hoop stress with the
// cell-averaged d ln sqrt f, which makes the toroidal field's magnetic pressure and hoop terms
// cancel in the radial source as in the continuum: the rest) moved the coarse number to 1.35e-2. That
// is truncation error of a correct scheme, not a lost balance: it converges faster than before
// (the old scheme went 6.4e-3 -> 2.4e-3, order 1.4) and is 3.9x below the unbalanced flow. So the
// bounds: the coarse residual below 1/3 of the unbalanced flow (measured 1/3.9), and a residual
// that shrinks by > 2.5 when dr halves (measured 3.4; an O(1) force imbalance, as the unbalanced
// model's, shrinks by ~1.4). Three-level parfile run (rotmag, 150 steps, t = 0.48): max |v_r| 8.7e-4
// vs 2.1e-2, |v_theta| 2.3e-4 vs 7.3e-3.
TEST(MagnetisedDrns, EquilibriumFieldKeepsTheStarAtRest) {
  const std::vector<std::string> fine = {"Grid::ncells=[128,128,1]", "Grid::block_size=[32,32,1]"};
  const double equilibrium = poloidal_speed_after(40, {});
  const double equilibrium_fine = poloidal_speed_after(80, fine);
  const double unbalanced = poloidal_speed_after(40, {"RotatingStar::K_m=0"});
  std::printf("max poloidal speed at t = 2: magnetised equilibrium %.3e (dr = 1.56), %.3e (dr = 0.78, ratio %.2f); "
              "unmagnetised model with the field %.3e (dr = 1.56)\n",
              equilibrium, equilibrium_fine, equilibrium / equilibrium_fine, unbalanced);
  EXPECT_LT(equilibrium, unbalanced / 3);
  EXPECT_GT(equilibrium / equilibrium_fine, 2.5);
  EXPECT_LT(equilibrium_fine, 5e-3);
}

TEST(MagnetisedDrns, FieldThatTheRunWouldNotEvolveIsRefused) {
  EXPECT_NE(error_of("drns_sph_2d.yaml", {"RotatingStar::K_m=3"}).find("HydroBase::magnetic_field = none evolves no field"),
            std::string::npos);
  EXPECT_NE(error_of("drns_sph_2d.yaml", {"RotatingStar::K_m=3", "HydroBase::magnetic_field=evolved"})
                .find("add SeedMagneticField to active_thorns"),
            std::string::npos);
  EXPECT_NE(error_of("magnetized_drns.yaml", {"SeedMagneticField::K_m=2"}).find("the grid's field would not be the equilibrium's"),
            std::string::npos);
}

}  // namespace
