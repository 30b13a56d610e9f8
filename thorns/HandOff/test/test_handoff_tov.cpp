// The hand-off end to end: the BU0 TOV star (K = 100, Gamma = 2, rho_c = 1.28e-3) written as 3D
// Carpet data (octant, two levels, two components each, ghost and buffer zones) and handed to a 2D
// cylindrical and a 3D Cartesian grid with parfiles/handoff_tov_cyl_2d.yaml: the imported rest mass
// equals the 3D rest mass on the grid to round-off, the 3D rest mass is the TOV's to the 3D data's
// discretisation error, and after XCFC's re-solve from the conserved variables rho_c, psi_c and
// alpha_c agree with the TOV solution to the grid's discretisation error.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <array>
#include <fstream>
#include <sstream>
#include <span>
#include <string>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "HandOff/handoff_state.hpp"
#include "TOV/tov_solver.hpp"
#include "remnant/driver.hpp"
#include "handoff_profiles.hpp"
#include "synthetic_carpet.hpp"
#include "tov_carpet_data.hpp"

namespace {

using namespace remnant;

struct TovCarpet : handoff_test::TovCarpetData {
  // omega: rigid rotation v = omega (-y, x, 0) inside the star (the data then have a mirror at
  // z = 0 only); b: a uniform Bvec^z of this strength.
  explicit TovCarpet(const std::vector<std::string>& variables, double omega = 0, double b = 0) : TovCarpetData("handoff_tov") {
    handoff::synthetic::SyntheticCarpet spec;
    spec.variables = variables;
    // Level 0: spacing 1 to 15.5 (avoid-origin points); level 1: spacing 0.5 to 10, the star's
    // isotropic radius is 8.13.
    spec.levels = {{1.0, {0.5, 0.5, 0.5}, {16, 16, 16}, 0}, {0.5, {0, 0, 0}, {21, 21, 21}, 1}};
    if (omega != 0) {  // a bitant: rotation breaks the mirrors x = 0 and y = 0
      spec.reflection = {false, false, true};
      spec.levels = {{1.0, {-15.5, -15.5, 0.5}, {32, 32, 16}, 0}, {0.5, {-10, -10, 0}, {41, 41, 21}, 1}};
    }
    spec.iterations = {1024};
    spec.time = 100;
    write(spec, [this, omega, b](const std::string& v, int, double x, double y, double z) {
      const tov::TovPoint p = star.at(std::sqrt(x * x + y * y + z * z));
      if (v == "HYDROBASE::vel[0]") return p.rho > 0 ? -omega * y : 0.0;
      if (v == "HYDROBASE::vel[1]") return p.rho > 0 ? omega * x : 0.0;
      if (v == "HYDROBASE::Bvec[2]") return b;
      if (v == "HYDROBASE::rho") return p.rho;
      if (v == "HYDROBASE::press") return p.press;
      if (v == "HYDROBASE::eps") return p.eps;
      if (v == "ADMBASE::alp") return p.alpha;
      if (v == "ADMBASE::gxx" || v == "ADMBASE::gyy" || v == "ADMBASE::gzz") return std::pow(p.psi, 4);
      return 0.0;  // velocities, off-diagonal metric
    });
  }
};

const std::vector<std::string> kAll = {"HYDROBASE::rho", "HYDROBASE::press", "HYDROBASE::eps", "HYDROBASE::vel[0]",
                                       "HYDROBASE::vel[1]", "HYDROBASE::vel[2]", "ADMBASE::alp", "ADMBASE::gxx",
                                       "ADMBASE::gxy", "ADMBASE::gxz", "ADMBASE::gyy", "ADMBASE::gyz", "ADMBASE::gzz"};

struct Result {
  handoff::HandOffReport report;
  analysis::StarDiagnostics first;
  std::string report_text;
  std::vector<std::array<double, 11>> profiles;  // handoff_profiles.tsv
};

Result hand_off(const TovCarpet& data, const std::vector<std::string>& overrides) {
  const auto out = data.dir / "out";
  std::vector<std::string> settings = {"MoL::final_time=0", "HandOff::buffer_zones=2", "Analysis::every=1",
                                       "Flesh::out_dir=" + out.string()};
  settings.insert(settings.end(), overrides.begin(), overrides.end());
  Simulation sim(handoff_test::compiled_catalog(), handoff_test::handoff_options(data, settings), MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  Result r;
  r.report = sim.context().service<handoff::HandOffState>("HandOff::state").report;
  r.first = sim.context().service<analysis::History>("Analysis::history").rows.front();
  std::ifstream in(out / "handoff_report.txt");
  r.report_text.assign(std::istreambuf_iterator<char>(in), {});
  r.profiles = handoff_test::read_handoff_profiles(out / "handoff_profiles.tsv");
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
  // Profiles along the grid's first two directions: 3D data and grid side by side.
  int lines[2] = {0, 0};
  for (const auto& v : r.profiles) {
    lines[static_cast<int>(v[0])]++;
    if (v[5] > 0.5 * c.rho) {  // inside the star: the re-solved grid against the 3D data at the same cell
      EXPECT_NEAR(v[6] / v[5], 1.0, 3 * rho_tol) << "line " << v[0] << " at " << v[1];
      EXPECT_NEAR(v[8] / v[7], 1.0, 10 * psi_tol) << "line " << v[0] << " at " << v[1];
    }
  }
  EXPECT_GE(lines[0], 12);
  EXPECT_GE(lines[1], 12);
}

std::string error_of(const TovCarpet& data, const std::vector<std::string>& overrides) {
  return handoff_test::message_of([&] { hand_off(data, overrides); });
}

TEST(HandOffTOV, CarpetToCylindrical2D) {
  const TovCarpet data(kAll);
  const Result r = hand_off(data, {});
  check(data, r, "3D Carpet -> 2D cylindrical", 2e-2, 2e-3, 2e-3);
}

// Under --debug the flesh poisons what a function declares it writes and checks what it leaves:
// HandOff's declarations hold (the import keeps the atmosphere's conserved variables it reads).
TEST(HandOffTOV, DeclarationsHoldUnderDebug) {
  const TovCarpet data(kAll);
  const Result plain = hand_off(data, {});
  const Result debug = hand_off(data, {"Flesh::debug=true"});
  EXPECT_EQ(debug.report.after.rest_mass, plain.report.after.rest_mass);
  EXPECT_EQ(debug.report.atmosphere_initial_mass, plain.report.atmosphere_initial_mass);
  EXPECT_EQ(debug.first.rho_c, plain.first.rho_c);
}

TEST(HandOffTOV, CarpetToSpherical2D) {
  const TovCarpet data(kAll);
  const Result r = hand_off(data, {"Grid::coordinates=spherical", "Grid::ncells=[48,16,1]", "Grid::block_size=[16,16,1]",
                                   "Grid::xmax=[12,1.5707963267948966,6.283185307179586]",
                                   "Grid::boundary_lower=[origin,axis,outflow]", "Grid::boundary_upper=[outflow,reflect,outflow]"});
  check(data, r, "3D Carpet -> 2D spherical (equatorial mirror)", 2e-2, 2e-3, 2e-3);
}

TEST(HandOffTOV, CarpetToCylindrical3D) {
  const TovCarpet data(kAll);
  const Result r = hand_off(data, {"Grid::dimension=3", "Grid::ncells=[24,24,8]", "Grid::block_size=[12,12,4]",
                                   "Grid::boundary_lower=[axis,reflect,periodic]", "Grid::boundary_upper=[outflow,outflow,periodic]"});
  check(data, r, "3D Carpet -> 3D cylindrical (R, z, phi)", 2e-2, 2e-3, 2e-3);
}

TEST(HandOffTOV, CarpetToCartesian3DOctant) {
  const TovCarpet data(kAll);
  const Result r = hand_off(data, {"Grid::coordinates=cartesian", "Grid::dimension=3", "Grid::ncells=[24,24,24]",
                                   "Grid::block_size=[12,12,12]", "Grid::xmax=[12,12,12]",
                                   "Grid::boundary_lower=[reflect,reflect,reflect]"});
  check(data, r, "3D Carpet -> 3D Cartesian octant", 2e-2, 2e-3, 2e-3);
}

}  // namespace

namespace {

// A rigidly rotating star (v = omega x r inside): S_i goes to S_R, S_z, S_phi (Appendix), J survives
// the interpolation, the phi-average and the normalisation to the interpolation error.
void check_rotation(const Result& r, const char* name) {
  const auto& h = r.report;
  std::printf("%s: J 3D all %.8e, on the grid %.8e, imported %.8e (%.2e), after %.8e (%.2e); M0 imported/3D - 1 = %.1e\n",
              name, h.source_all.angular_momentum, h.source_grid.angular_momentum, h.imported.angular_momentum,
              h.imported.angular_momentum / h.source_grid.angular_momentum - 1, h.after.angular_momentum,
              h.after.angular_momentum / h.source_grid.angular_momentum - 1, h.imported.rest_mass / h.source_grid.rest_mass - 1);
  EXPECT_GT(h.source_grid.angular_momentum, 0);
  EXPECT_NEAR(h.imported.angular_momentum / h.source_grid.angular_momentum, 1.0, 2e-3);
  EXPECT_NEAR(h.after.angular_momentum / h.source_grid.angular_momentum, 1.0, 2e-3);
  EXPECT_NEAR(h.imported.rest_mass / h.source_grid.rest_mass, 1.0, 1e-13);
}

}  // namespace

TEST(HandOffTOV, RotatingCarpetToCylindrical2D) {
  const TovCarpet data(kAll, 0.01);
  check_rotation(hand_off(data, {}), "rotating, 3D Carpet bitant -> 2D cylindrical");
  check_rotation(hand_off(data, {"HandOff::cell_samples=2"}), "rotating, 3D Carpet bitant -> 2D cylindrical, cell averages of 2x2 rings");
}

TEST(HandOffTOV, RotatingCarpetToCartesian3DBitant) {
  const TovCarpet data(kAll, 0.01);
  check_rotation(hand_off(data, {"Grid::coordinates=cartesian", "Grid::dimension=3", "Grid::ncells=[24,24,12]",
                                 "Grid::block_size=[12,12,12]", "Grid::xmin=[-12,-12,0]", "Grid::xmax=[12,12,12]",
                                 "Grid::boundary_lower=[outflow,outflow,reflect]"}),
                 "rotating, 3D Carpet bitant -> 3D Cartesian bitant");
}

// Bad input stops the run before any evolution, naming the file, the variable and the parameter.
TEST(HandOffTOV, BadInput) {
  {  // a variable the data lack, with missing_variables = error
    const TovCarpet data({"HYDROBASE::rho", "HYDROBASE::vel[0]", "HYDROBASE::vel[1]", "HYDROBASE::vel[2]", "ADMBASE::gxx"});
    const std::string e = error_of(data, {"HandOff::missing_variables=error"});
    EXPECT_NE(e.find("'Ye'"), std::string::npos) << e;
    EXPECT_NE(e.find(data.files.front()), std::string::npos) << e;
    EXPECT_NE(e.find("HandOff::missing_variables"), std::string::npos) << e;
  }
  const TovCarpet data(kAll);
  {  // an iteration the data do not have
    const std::string e = error_of(data, {"HandOff::iteration=2048"});
    EXPECT_NE(e.find("iteration 2048"), std::string::npos) << e;
    EXPECT_NE(e.find("1024"), std::string::npos) << e;
    EXPECT_NE(e.find(".h5"), std::string::npos) << e;
    EXPECT_NE(e.find("HandOff::iteration"), std::string::npos) << e;
  }
  {  // a grid that cuts the star (isotropic radius 8.13)
    const std::string e = error_of(data, {"Grid::xmax=[6,6,6.283185307179586]", "Grid::ncells=[32,32,1]"});
    EXPECT_NE(e.find("cuts the star"), std::string::npos) << e;
    EXPECT_NE(e.find("Grid::xmax"), std::string::npos) << e;
  }
  {  // an EOS the data do not follow: p = (Gamma - 1) rho eps with Gamma = 2.5 is 50 % off
    const std::string e = error_of(data, {"EOS::gamma=2.5"});
    EXPECT_NE(e.find("'press'"), std::string::npos) << e;
    EXPECT_NE(e.find(data.files.front()), std::string::npos) << e;
    EXPECT_NE(e.find("HandOff::eos_tolerance"), std::string::npos) << e;
  }
  {  // no files, a metric initialisation that would overwrite the import, a grid HandOff cannot fill
    std::string e = error_of(data, {"HandOff::files=[]"});
    EXPECT_NE(e.find("HandOff::files is empty"), std::string::npos) << e;
    e = error_of(data, {"XCFC::initial_metric=from_primitives"});
    EXPECT_NE(e.find("XCFC::initial_metric must be from_conserved"), std::string::npos) << e;
    EXPECT_NE(e.find("command line argument"), std::string::npos) << e;  // where it was set
    e = error_of(data, {"Grid::coordinates=spherical", "Grid::dimension=1", "Grid::ncells=[48,1,1]", "Grid::block_size=[16,1,1]",
                        "Grid::boundary_lower=[origin,outflow,outflow]", "Grid::xmax=[12,3.141592653589793,6.283185307179586]"});
    EXPECT_NE(e.find("Grid::dimension"), std::string::npos) << e;
    EXPECT_NE(e.find("HandOff fills 3D grids"), std::string::npos) << e;
  }
  {  // files that do not exist
    const std::string e = error_of(data, {"HandOff::files=[/nonexistent/run/*.h5]"});
    EXPECT_NE(e.find("/nonexistent/run/*.h5"), std::string::npos) << e;
    EXPECT_NE(e.find("HandOff::files"), std::string::npos) << e;
  }
}

TEST(HandOffTOV, MagneticFieldIsRefusedUnlessIgnored) {
  std::vector<std::string> vars = kAll;
  vars.push_back("HYDROBASE::Bvec[2]");
  const TovCarpet data(vars, 0.0, 1e-6);
  const std::string e = error_of(data, {});
  EXPECT_NE(e.find("Bvec"), std::string::npos) << e;
  EXPECT_NE(e.find("HandOff::ignore_magnetic_field"), std::string::npos) << e;
  EXPECT_NE(e.find(data.files.front()), std::string::npos) << e;
  // Dropped on request: the fluid is handed off as without it.
  const Result r = hand_off(data, {"HandOff::ignore_magnetic_field=true"});
  EXPECT_NEAR(r.report.imported.rest_mass / r.report.source_grid.rest_mass, 1.0, 1e-13);
}

// HandOff::centre off a mirror plane of the data: the unfolded data are symmetric about the plane,
// so their centre lies on it; a non-zero component along a mirrored axis is an input error naming
// the parameter, its value, the mirrored axis (and where the mirror came from) and what is allowed.
TEST(HandOffTOV, CentreOffAMirrorPlaneIsAnError) {
  const TovCarpet data(kAll);  // an octant: the files declare the mirrors x, y, z = 0
  std::string e = error_of(data, {"HandOff::centre=[0,0,6]"});
  EXPECT_NE(e.find("HandOff::centre"), std::string::npos) << e;
  EXPECT_NE(e.find("command line argument"), std::string::npos) << e;  // where it was set
  EXPECT_NE(e.find("z = 6"), std::string::npos) << e;
  EXPECT_NE(e.find("mirrored across z = 0"), std::string::npos) << e;
  EXPECT_NE(e.find("ReflectionSymmetry::reflection_z"), std::string::npos) << e;
  EXPECT_NE(e.find("HandOff::centre[2] = 0"), std::string::npos) << e;
  // A mirror the user names is checked with the parameters, before any file is read.
  e = error_of(data, {"HandOff::files=[/nonexistent/run/*.h5]", "HandOff::reflection=[y]", "HandOff::centre=[0,-2.5,0]"});
  EXPECT_NE(e.find("y = -2.5"), std::string::npos) << e;
  EXPECT_NE(e.find("(HandOff::reflection)"), std::string::npos) << e;
  EXPECT_NE(e.find("HandOff::centre[1] = 0"), std::string::npos) << e;
}
