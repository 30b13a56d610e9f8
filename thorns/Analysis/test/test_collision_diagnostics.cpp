// The collision diagnostics against analytic cases:
// - a TOV star (BU0, its exact isotropic metric on a 3D octant): M_adm = M_komar = M, M_rest = M0,
//   whole-space values from the octant (x 8);
// - the quadrupole formula on a prescribed oscillating pair of Gaussian blobs (flat space, dust-like
//   momentum), z_c(t) = z0 + a cos(w t) and its mirror: I = 2 m z_c^2, dI/dt = 4 m z_c z_c',
//   h+ D = 4 m (z_c'^2 + z_c z_c''); the momentum moment is the time derivative of the density's;
// - the columns are added only when asked (the default TSV header is unchanged).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "Analysis/collision_diagnostics.hpp"
#include "Analysis/star_diagnostics.hpp"
#include "TOV/cold_slice.hpp"
#include "TOV/tov_solver.hpp"
#include "remnant/driver.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

// BU0 on a 3D octant [0, 16]^3, no evolution.
std::unique_ptr<Simulation> octant_star(int n, std::vector<std::string> extra = {"Analysis::collision_diagnostics=always"}) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  static int count = 0;
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/bu0_cow.yaml";
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() /
                   ("remnant_collision_" + std::to_string(::getpid()) + "_" + std::to_string(count++));
  const std::string N = std::to_string(n);
  o.overrides = {"Grid::coordinates=cartesian", "Grid::dimension=3", "Grid::ncells=[" + N + "," + N + "," + N + "]",
                 "Grid::block_size=[16,16,16]", "Grid::xmin=[0,0,0]", "Grid::xmax=[16,16,16]",
                 "Grid::boundary_lower=[reflect,reflect,reflect]", "MoL::max_iterations=0", "MoL::final_time=-1",
                 "Flesh::out_dir=" + out.string()};
  o.overrides.insert(o.overrides.end(), extra.begin(), extra.end());
  auto sim = std::make_unique<Simulation>(catalog, o, MPI_COMM_WORLD);
  sim->setup_output_and_grid();
  sim->run();
  return sim;
}

}  // namespace

TEST(CollisionDiagnostics, MassesOfATovStar) {
  const auto slice = tov::polytrope_slice(100.0, 2.0, 0.5);
  const tov::TovStar star(*slice, 1.28e-3);
  auto sim = octant_star(32);
  const auto& row = sim->context().service<analysis::History>("Analysis::history").rows.back();
  ASSERT_TRUE(row.collision);
  const double M = star.gravitational_mass(), M0 = star.rest_mass();
  std::printf("BU0 on an octant, dx = 0.5: M_adm %.6f, M_komar %.6f (M = %.6f), M_rest %.6f (M0 = %.6f)\n", row.col.M_adm,
              row.col.M_komar, M, row.col.M_rest, M0);
  EXPECT_NEAR(row.col.M_adm / M, 1.0, 5e-4);
  EXPECT_NEAR(row.col.M_komar / M, 1.0, 5e-4);
  EXPECT_NEAR(row.col.M_rest / M0, 1.0, 5e-4);
  EXPECT_NEAR(row.col.M_rest, 8 * row.rest_mass, 1e-13 * M0);
  EXPECT_EQ(row.rho_max_norm, 1.0);
  EXPECT_EQ(row.col.z_max_lower, -row.col.z_max_upper);  // equatorial symmetry: the mirror
  // The point value at the maximum (the corner cell at the origin) against the corner cell's value.
  // The initial data are point values at the cell centroids, not averages: the fit, which takes them
  // as averages, keeps h dx^2 / 12 per direction of the raw offset's h (dx/2)^2, a third of it.
  std::printf("rho_c %.8e: rho_max %.8e, rho_max_point %.8e\n", 1.28e-3, row.rho_max, row.col.rho_max_point);
  EXPECT_LT(std::abs(row.col.rho_max_point - 1.28e-3), 0.4 * (1.28e-3 - row.rho_max));
  EXPECT_EQ(row.rho_max_point_norm, 1.0);
}

TEST(CollisionDiagnostics, QuadrupoleOfAnOscillatingPair) {
  auto sim = octant_star(32);
  Context& ctx = sim->context();
  const double m = 0.01, sigma = 1.2, z0 = 8, a = 1.5, w = 0.05, pi = std::numbers::pi;
  const double norm = m / std::pow(2 * pi * sigma * sigma, 1.5);
  auto zc = [&](double t) { return z0 + a * std::cos(w * t); };
  auto zdot = [&](double t) { return -a * w * std::sin(w * t); };
  auto zddot = [&](double t) { return -a * w * w * std::cos(w * t); };
  // The pair at time t written into the matter (flat metric, no pressure): D = m G, S_z = D v_z.
  auto set = [&](double t) {
    for (Block* b : ctx.grid().local_blocks()) {
      const vars::HydroBase::prim p(ctx, *b);
      const vars::HydroBase::cons c(ctx, *b);
      const vars::Spacetime::metric g(ctx, *b);
      for_interior(*b, [&](int i, int j, int k) {
        const double x = b->x(0, i), y = b->x(1, j), z = b->x(2, k), r2 = x * x + y * y;
        const double up = norm * std::exp(-(r2 + (z - zc(t)) * (z - zc(t))) / (2 * sigma * sigma));
        const double down = norm * std::exp(-(r2 + (z + zc(t)) * (z + zc(t))) / (2 * sigma * sigma));
        c.D(i, j, k) = up + down;
        c.tau(i, j, k) = 0;
        c.S(0, i, j, k) = c.S(1, i, j, k) = 0;
        c.S(2, i, j, k) = zdot(t) * (up - down);
        p.rho(i, j, k) = up + down;
        p.press(i, j, k) = 0;
        p.vel(0, i, j, k) = p.vel(1, i, j, k) = 0;
        p.vel(2, i, j, k) = c.S(2, i, j, k) / c.D(i, j, k);
        g.psi(i, j, k) = g.alpha(i, j, k) = 1;
        for (int d = 0; d < 3; ++d) g.beta(d, i, j, k) = 0;
      });
    }
    return analysis::collision_diagnostics(ctx);
  };
  double worst_I = 0, worst_dI = 0, worst_identity = 0, worst_h = 0;
  const double dt = 0.5;
  for (double t : {3.0, 17.0, 31.0, 45.0}) {
    const auto c = set(t), before = set(t - dt), after = set(t + dt);
    const double I = 2 * m * zc(t) * zc(t), dI = 4 * m * zc(t) * zdot(t);
    const double h = 4 * m * (zdot(t) * zdot(t) + zc(t) * zddot(t));  // D h+ in the equatorial plane
    const double scale_dI = 4 * m * z0 * a * w, scale_h = 4 * m * a * w * w * z0;
    worst_I = std::max(worst_I, std::abs(c.quad_I / I - 1));
    worst_dI = std::max(worst_dI, std::abs(c.quad_dI - dI) / scale_dI);
    worst_identity = std::max(worst_identity, std::abs((after.quad_I - before.quad_I) / (2 * dt) - c.quad_dI) / scale_dI);
    worst_h = std::max(worst_h, std::abs((after.quad_dI - before.quad_dI) / (2 * dt) - h) / scale_h);
    EXPECT_NEAR(c.z_max_upper, zc(t), 0.25 + 1e-12);  // the cell nearest the blob's centre (dx = 0.5)
  }
  std::printf("oscillating pair: I %.2e, dI/dt %.2e, dI/dt vs the change of I %.2e, D h+ %.2e (relative errors)\n",
              worst_I, worst_dI, worst_identity, worst_h);
  EXPECT_LT(worst_I, 1e-6);
  EXPECT_LT(worst_dI, 1e-6);
  EXPECT_LT(worst_identity, 1e-3);  // O(dt^2) of the centred difference
  EXPECT_LT(worst_h, 1e-3);
}

TEST(CollisionDiagnostics, ColumnsOnlyWhenAsked) {
  auto plain = octant_star(16, {});
  const auto& row = plain->context().service<analysis::History>("Analysis::history").rows.back();
  EXPECT_FALSE(row.collision);
  // The collision columns come after everything else (rotation and magnetic columns included).
  for (bool rotation : {false, true})
    for (bool magnetic : {false, true}) {
      const std::string plain = analysis::tsv_header(rotation, magnetic);
      const std::string h = analysis::tsv_header(rotation, magnetic, true);
      EXPECT_EQ(h.rfind(plain.substr(0, plain.size() - 1) + "\trho_max_norm\t", 0), 0u) << h;
      EXPECT_NE(h.find("\th_plus\t"), std::string::npos);
    }
}
