// Remnant to Remnant: a 3D Cartesian octant run of BU0 (parfiles/handoff_source_tov_3d.yaml) writes
// its HDF5 volume output; HandOff (format remnant, mirrors x, y, z) hands it to 2D cylindrical
// coordinates (parfiles/handoff_tov_cyl_2d.yaml). The 3D rest mass read back is eight times the
// octant run's own to round-off, the imported rest mass is the 3D rest mass on the grid to
// round-off, and the 2D star after XCFC's re-solve has the 3D run's rho_c and psi_c to the
// resolution's error.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>

#include "Analysis/star_diagnostics.hpp"
#include "HandOff/handoff_state.hpp"
#include "remnant/driver.hpp"
#include "remnant/vars/HydroBase.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

struct RunResult {
  analysis::StarDiagnostics first;
  handoff::HandOffReport report;
  double angular_momentum = 0;  // sum of S_phi dV on a cylindrical grid
};

RunResult run(const std::string& parfile, std::vector<std::string> overrides, bool handoff) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/" + parfile;
  o.quiet = true;
  o.overrides = std::move(overrides);
  o.overrides.push_back("MoL::final_time=0");
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  RunResult r;
  r.first = sim.context().service<analysis::History>("Analysis::history").rows.front();
  Context& ctx = sim.context();
  if (ctx.grid().coordinates() == CoordinateSystem::cylindrical) {
    double J = 0;
    for (Block* blk : ctx.grid().local_blocks()) {
      const vars::HydroBase::cons cons(ctx, *blk);
      for_interior(*blk, [&](int i, int j, int k) { J += cons.S(2, i, j, k) * blk->cell_volume(i, j, k); });
    }
    MPI_Allreduce(&J, &r.angular_momentum, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  }
  if (handoff) r.report = sim.context().service<handoff::HandOffState>("HandOff::state").report;
  return r;
}

TEST(HandOffRoundTrip, Remnant3DOctantToCylindrical2D) {
  long pid = static_cast<long>(::getpid());
  MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  const auto dir = std::filesystem::temp_directory_path() / ("handoff_roundtrip_" + std::to_string(pid));
  const RunResult a = run("handoff_source_tov_3d.yaml", {"Flesh::out_dir=" + (dir / "3d").string()}, false);
  const std::string file = (dir / "3d" / "grid-volume.it00000000.h5").string();
  ASSERT_TRUE(std::filesystem::exists(file)) << file;
  const RunResult b = run("handoff_tov_cyl_2d.yaml",
                    {"Flesh::out_dir=" + (dir / "2d").string(), "HandOff::format=remnant", "HandOff::reflection=[x,y,z]",
                     "HandOff::files=[" + file + "]"},
                    true);
  MPI_Barrier(MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::filesystem::remove_all(dir);
  const auto& h = b.report;
  std::printf("round trip: 3D octant M0 %.12f (x8 = %.12f), read back %.12f (%.1e); on the 2D grid %.10f, imported %.10f "
              "(%.1e), normalisation %.6f; rho_c 3D %.6e 2D %.6e (%.2e); psi_c 3D %.6f 2D %.6f (%.2e); alpha_c 3D %.6f "
              "2D %.6f (%.2e)\n",
              a.first.rest_mass, 8 * a.first.rest_mass, h.source_all.rest_mass, h.source_all.rest_mass / (8 * a.first.rest_mass) - 1,
              h.source_grid.rest_mass, h.imported.rest_mass, h.imported.rest_mass / h.source_grid.rest_mass - 1, h.normalisation,
              a.first.rho_c, b.first.rho_c, b.first.rho_c / a.first.rho_c - 1, a.first.psi_c, b.first.psi_c,
              b.first.psi_c / a.first.psi_c - 1, a.first.alpha_c, b.first.alpha_c, b.first.alpha_c / a.first.alpha_c - 1);
  EXPECT_NEAR(h.source_all.rest_mass / (8 * a.first.rest_mass), 1.0, 1e-12);
  EXPECT_NEAR(h.imported.rest_mass / h.source_grid.rest_mass, 1.0, 1e-13);
  EXPECT_LT(h.outside_fraction, 1e-6);  // the atmosphere in the cube's corners beyond R = 12
  EXPECT_NEAR(b.first.rho_c / a.first.rho_c, 1.0, 2e-2);
  EXPECT_NEAR(b.first.psi_c / a.first.psi_c, 1.0, 2e-3);
  EXPECT_NEAR(b.first.alpha_c / a.first.alpha_c, 1.0, 3e-3);
  EXPECT_LT(h.psi4_max_rel, 1e-2);  // the 3D run's psi^4 against the 2D re-solve
}

}  // namespace

// The round trip with a rotating star: RotatingStar (r_p/r_e = 0.8) on a 3D Cartesian grid
// with a mirror at z = 0 (parfiles/handoff_source_rns_3d.yaml, spacing 1 and 0.5), handed to 2D
// cylindrical (spacing 0.25), against RotatingStar's own 2D model on parfiles/rns_uniform_cyl_2d.yaml
// (spacing 0.25 around the star): rho_c, M0 and J converge to it with the 3D resolution, and at 0.5
// agree to 1.5 %, 5e-4 and 1.5e-3; handed to 2D spherical instead, the same to 2 %, 5e-4, 2e-3.
TEST(HandOffRoundTrip, RotatingStar3DToCylindrical2D) {
  long pid = static_cast<long>(::getpid());
  MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  const auto dir = std::filesystem::temp_directory_path() / ("handoff_rns_" + std::to_string(pid));
  const RunResult id2d = run("rns_uniform_cyl_2d.yaml", {"Flesh::out_dir=" + (dir / "id2d").string(), "RotatingStar::axis_ratio=0.8",
                                                         "XCFC::solve_every=1"}, false);
  double rho[2], m0[2], j[2];
  for (int r = 0; r < 2; ++r) {
    const std::string cells = r == 0 ? "[32,32,16]" : "[64,64,32]";
    const auto out3d = dir / ("3d_" + std::to_string(r));
    run("handoff_source_rns_3d.yaml", {"Flesh::out_dir=" + out3d.string(), "Grid::ncells=" + cells}, false);
    const RunResult b = run("handoff_tov_cyl_2d.yaml",
                            {"Flesh::out_dir=" + (dir / ("2d_" + std::to_string(r))).string(), "HandOff::format=remnant",
                             "HandOff::reflection=[z]", "HandOff::files=[" + (out3d / "grid-volume.it00000000.h5").string() + "]",
                             "Grid::ncells=[64,64,1]", "Grid::xmax=[16,16,6.283185307179586]"},
                            true);
    rho[r] = b.first.rho_c;
    m0[r] = b.report.after.rest_mass;
    j[r] = b.angular_momentum;
    EXPECT_NEAR(b.report.imported.rest_mass / b.report.source_grid.rest_mass, 1.0, 1e-13);
  }
  // The finer 3D data to 2D spherical (r, theta; equatorial mirror): the same M0 and J.
  const RunResult sph = run("handoff_tov_cyl_2d.yaml",
                            {"Flesh::out_dir=" + (dir / "2d_sph").string(), "HandOff::format=remnant", "HandOff::reflection=[z]",
                             "HandOff::files=[" + (dir / "3d_1" / "grid-volume.it00000000.h5").string() + "]",
                             "Grid::coordinates=spherical", "Grid::ncells=[64,32,1]",
                             "Grid::xmax=[16,1.5707963267948966,6.283185307179586]",
                             "Grid::boundary_lower=[origin,axis,outflow]", "Grid::boundary_upper=[outflow,reflect,outflow]"},
                            true);
  MPI_Barrier(MPI_COMM_WORLD);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::filesystem::remove_all(dir);
  const double rho2d = id2d.first.rho_c, m02d = id2d.first.rest_mass, j2d = id2d.angular_momentum;
  std::printf("rotating round trip: 2D model rho_c %.6e M0 %.8f; hand-off from 3D spacing 1, 0.5: rho_c %.6e %.6e (%.2e %.2e), "
              "M0 %.8f %.8f (%.2e %.2e), J %.8f %.8f (%.2e %.2e; 2D model %.8f)\n",
              rho2d, m02d, rho[0], rho[1], rho[0] / rho2d - 1, rho[1] / rho2d - 1, m0[0], m0[1], m0[0] / m02d - 1, m0[1] / m02d - 1,
              j[0], j[1], j[0] / j2d - 1, j[1] / j2d - 1, j2d);
  EXPECT_LT(std::abs(rho[1] / rho2d - 1), std::abs(rho[0] / rho2d - 1) / 3);  // converges with the 3D spacing
  EXPECT_NEAR(rho[1] / rho2d, 1.0, 1.5e-2);
  EXPECT_NEAR(m0[1] / m02d, 1.0, 5e-4);
  EXPECT_LT(std::abs(j[1] / j2d - 1), std::abs(j[0] / j2d - 1) / 2);
  EXPECT_NEAR(j[1] / j2d, 1.0, 1.5e-3);
  std::printf("rotating round trip to 2D spherical: rho_c %.6e (%.2e), M0 %.8f (%.2e), J %.8f (%.2e)\n", sph.first.rho_c,
              sph.first.rho_c / rho2d - 1, sph.report.after.rest_mass, sph.report.after.rest_mass / m02d - 1,
              sph.report.after.angular_momentum, sph.report.after.angular_momentum / j2d - 1);
  EXPECT_NEAR(sph.report.imported.rest_mass / sph.report.source_grid.rest_mass, 1.0, 1e-13);
  EXPECT_NEAR(sph.first.rho_c / rho2d, 1.0, 2e-2);
  EXPECT_NEAR(sph.report.after.rest_mass / m02d, 1.0, 5e-4);
  EXPECT_NEAR(sph.report.after.angular_momentum / j2d, 1.0, 2e-3);
}
