// The hand-off end to end: the BU0 TOV star (K = 100, Gamma = 2, rho_c = 1.28e-3) written as 3D
// Carpet data (octant, two levels, two components each, ghost and buffer zones) and handed to a 2D
// cylindrical and a 3D Cartesian grid with parfiles/handoff_tov_cyl_2d.yaml: the imported rest mass
// equals the 3D rest mass on the grid to round-off, the 3D rest mass is the TOV's to the 3D data's
// discretisation error, and after XCFC's re-solve from the conserved variables rho_c, psi_c and
// alpha_c agree with the TOV solution to the grid's discretisation error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "HandOff/handoff_state.hpp"
#include "TOV/tov_solver.hpp"
#include "remnant/driver.hpp"
#include "synthetic_carpet.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

struct TovCarpet {
  std::unique_ptr<tov::ColdSlice> slice = tov::polytrope_slice(100.0, 2.0, 0.5);
  tov::TovStar star{*slice, 1.28e-3};
  std::filesystem::path dir;
  std::vector<std::string> files;
  explicit TovCarpet(const std::vector<std::string>& variables) {
    dir = std::filesystem::temp_directory_path() / ("handoff_tov_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    handoff::synthetic::SyntheticCarpet spec;
    spec.variables = variables;
    // Level 0: spacing 1 to 15.5 (avoid-origin points); level 1: spacing 0.5 to 10, the star's
    // isotropic radius is 8.13.
    spec.levels = {{1.0, {0.5, 0.5, 0.5}, {16, 16, 16}, 0}, {0.5, {0, 0, 0}, {21, 21, 21}, 1}};
    spec.iterations = {1024};
    spec.time = 100;
    files = handoff::synthetic::write_synthetic_carpet(dir.string(), spec, [this](const std::string& v, int, double x, double y, double z) {
      const tov::TovPoint p = star.at(std::sqrt(x * x + y * y + z * z));
      if (v == "HYDROBASE::rho") return p.rho;
      if (v == "HYDROBASE::press") return p.press;
      if (v == "HYDROBASE::eps") return p.eps;
      if (v == "ADMBASE::alp") return p.alpha;
      if (v == "ADMBASE::gxx" || v == "ADMBASE::gyy" || v == "ADMBASE::gzz") return std::pow(p.psi, 4);
      return 0.0;  // velocities, off-diagonal metric
    });
  }
  ~TovCarpet() { std::filesystem::remove_all(dir); }
};

const std::vector<std::string> kAll = {"HYDROBASE::rho", "HYDROBASE::press", "HYDROBASE::eps", "HYDROBASE::vel[0]",
                                       "HYDROBASE::vel[1]", "HYDROBASE::vel[2]", "ADMBASE::alp", "ADMBASE::gxx",
                                       "ADMBASE::gxy", "ADMBASE::gxz", "ADMBASE::gyy", "ADMBASE::gyz", "ADMBASE::gzz"};

struct Result {
  handoff::HandOffReport report;
  analysis::StarDiagnostics first;
  std::string report_text;
};

Result hand_off(const TovCarpet& data, std::vector<std::string> overrides) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/handoff_tov_cyl_2d.yaml";
  o.quiet = true;
  const auto out = data.dir / "out";
  std::string files = "HandOff::files=[";
  for (std::size_t i = 0; i < data.files.size(); ++i) files += (i ? "," : "") + data.files[i];
  o.overrides = std::move(overrides);
  o.overrides.push_back(files + "]");
  o.overrides.push_back("MoL::final_time=0");
  o.overrides.push_back("HandOff::buffer_zones=2");
  o.overrides.push_back("Analysis::every=1");
  o.overrides.push_back("Flesh::out_dir=" + out.string());
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  Result r;
  r.report = sim.context().service<handoff::HandOffState>("HandOff::state").report;
  r.first = sim.context().service<analysis::History>("Analysis::history").rows.front();
  std::ifstream in(out / "handoff_report.txt");
  r.report_text.assign(std::istreambuf_iterator<char>(in), {});
  return r;
}

void check(const TovCarpet& data, const Result& r, const char* name, double rho_tol, double psi_tol, double alpha_tol) {
  const auto& h = r.report;
  const tov::TovPoint c = data.star.at(0);
  std::printf("%s: M0 3D all %.8f (TOV %.8f, %.2e), on the grid %.10f, imported %.10f (%.1e), normalisation %.8f, "
              "outside %.1e; after: M0 %.10f, J %.2e, E %.8f (3D %.8f); rho_c %.6e (TOV %.6e, %.2e), psi_c %.6f (TOV %.6f, "
              "%.2e), alpha_c %.6f (TOV %.6f, %.2e); psi^4/gamma^(1/3) max %.2e mean %.2e, alpha max %.2e mean %.2e\n",
              name, h.source_all.rest_mass, data.star.rest_mass(), h.source_all.rest_mass / data.star.rest_mass() - 1,
              h.source_grid.rest_mass, h.imported.rest_mass, h.imported.rest_mass / h.source_grid.rest_mass - 1,
              h.normalisation, h.outside_fraction, h.after.rest_mass, h.after.angular_momentum, h.after.energy,
              h.source_grid.energy, r.first.rho_c, c.rho, r.first.rho_c / c.rho - 1, r.first.psi_c, c.psi,
              r.first.psi_c / c.psi - 1, r.first.alpha_c, c.alpha, r.first.alpha_c / c.alpha - 1, h.psi4_max_rel,
              h.psi4_mean_rel, h.alpha_max_rel, h.alpha_mean_rel);
  // Exactly the 3D rest mass on the grid (round-off), and the TOV's to the 3D discretisation.
  EXPECT_NEAR(h.imported.rest_mass / h.source_grid.rest_mass, 1.0, 1e-13);
  EXPECT_NEAR(h.source_all.rest_mass / data.star.rest_mass(), 1.0, 1e-2);
  EXPECT_LT(h.outside_fraction, 1e-12);
  EXPECT_NEAR(h.normalisation, 1.0, 2e-2);
  // Only the atmosphere changes the rest mass after the import: empty cells, and cells the recovery
  // made atmosphere (HydroBase::mass_budget's source).
  EXPECT_NEAR((h.after.rest_mass - h.atmosphere_mass - h.atmosphere_initial_mass) / h.imported.rest_mass, 1.0, 1e-13);
  EXPECT_NEAR(h.after.angular_momentum, 0.0, 1e-12);
  // The re-solved metric and the recovered density: the TOV solution to discretisation error.
  EXPECT_NEAR(r.first.rho_c / c.rho, 1.0, rho_tol);
  EXPECT_NEAR(r.first.psi_c / c.psi, 1.0, psi_tol);
  EXPECT_NEAR(r.first.alpha_c / c.alpha, 1.0, alpha_tol);
  EXPECT_LT(h.psi4_max_rel, 10 * psi_tol);
  EXPECT_LT(h.alpha_max_rel, 10 * alpha_tol);
  EXPECT_NE(r.report_text.find("psi4_vs_gamma13_max"), std::string::npos);
  EXPECT_NE(r.report_text.find("outside_fraction"), std::string::npos);
}

TEST(HandOffTOV, CarpetToCylindrical2D) {
  const TovCarpet data(kAll);
  const Result r = hand_off(data, {});
  check(data, r, "3D Carpet -> 2D cylindrical", 2e-2, 2e-3, 2e-3);
}

TEST(HandOffTOV, CarpetToCartesian3DOctant) {
  const TovCarpet data(kAll);
  const Result r = hand_off(data, {"Grid::coordinates=cartesian", "Grid::dimension=3", "Grid::ncells=[24,24,24]",
                                   "Grid::block_size=[12,12,12]", "Grid::xmax=[12,12,12]",
                                   "Grid::boundary_lower=[reflect,reflect,reflect]"});
  check(data, r, "3D Carpet -> 3D Cartesian octant", 2e-2, 2e-3, 2e-3);
}

}  // namespace
