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

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

struct RunResult {
  analysis::StarDiagnostics first;
  handoff::HandOffReport report;
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
