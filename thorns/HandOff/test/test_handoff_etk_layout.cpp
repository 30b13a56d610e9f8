// Structures of real Einstein Toolkit output (the kuibit project's TOV run, read for the README),
// reproduced synthetically: GRHydro's atmosphere floor (rho_abs_min = 1e-10) fills the whole
// Carpet domain, an octant [0, 480]^3 here as the TOV star's 5-level grid there: unfolded, the
// floor holds 5 % of the star's rest mass, all of it outside a grid around the star. The hand-off
// counts only the matter above the data's atmosphere against HandOff::max_outside_fraction (every
// point before: "the grid cuts the star"), and still imports all the data on the grid.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "HandOff/handoff_state.hpp"
#include "TOV/tov_solver.hpp"
#include "remnant/driver.hpp"
#include "synthetic_carpet.hpp"
#include "tov_carpet_data.hpp"

namespace {

using namespace remnant;

constexpr double kFloor = 1e-10;  // GRHydro::rho_abs_min of the real run

struct FlooredTov : handoff_test::TovCarpetData {
  // metric = false: only HydroBase variables (the kuibit run's 3D output has rho and vel alone).
  explicit FlooredTov(bool metric = true) : TovCarpetData(metric ? "handoff_etk" : "handoff_etk_nometric") {
    handoff::synthetic::SyntheticCarpet spec;
    spec.variables = {"HYDROBASE::rho", "HYDROBASE::press", "HYDROBASE::eps"};
    if (metric)
      for (const char* g : {"gxx", "gxy", "gxz", "gyy", "gyz", "gzz"}) spec.variables.push_back(std::string("ADMBASE::") + g);
    // Spacing 16 to 480 (the real run: 8 to 240), halved per level to 0.5 on [0, 10].
    spec.levels = {{16, {0, 0, 0}, {31, 31, 31}, 2}, {8, {0, 0, 0}, {13, 13, 13}, 2}, {4, {0, 0, 0}, {13, 13, 13}, 2},
                   {2, {0, 0, 0}, {13, 13, 13}, 2}, {1, {0, 0, 0}, {17, 17, 17}, 2}, {0.5, {0, 0, 0}, {21, 21, 21}, 2}};
    spec.ghosts_written = false;  // out3D_ghosts = no, as there
    spec.ghosts_parameter = "out3D_ghosts";
    spec.stem = "tov.xyz";
    spec.buffer = 0;
    write(spec, [this](const std::string& v, int, double x, double y, double z) {
      const tov::TovPoint p = star.at(std::sqrt(x * x + y * y + z * z));
      if (v == "HYDROBASE::rho") return std::max(p.rho, kFloor);
      if (v == "HYDROBASE::press") return 100.0 * std::pow(std::max(p.rho, kFloor), 2.0);
      if (v == "HYDROBASE::eps") return 100.0 * std::max(p.rho, kFloor);
      if (v == "ADMBASE::gxx" || v == "ADMBASE::gyy" || v == "ADMBASE::gzz") return std::pow(p.psi, 4);
      return 0.0;
    });
  }
};

handoff::HandOffReport hand_off(const FlooredTov& data, const std::vector<std::string>& more) {
  std::vector<std::string> settings = {"MoL::final_time=0", "HandOff::buffer_zones=0", "Flesh::out_dir=" + (data.dir / "out").string()};
  settings.insert(settings.end(), more.begin(), more.end());
  Simulation sim(handoff_test::compiled_catalog(), handoff_test::handoff_options(data, settings), MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  return sim.context().service<handoff::HandOffState>("HandOff::state").report;
}

TEST(HandOffEtkLayout, AtmosphereFloorOverTheDomainIsNotOutside) {
  const FlooredTov data;
  const handoff::HandOffReport h = hand_off(data, {});
  const double floor_share = 1 - h.source_matter_rest_mass / h.source_all.rest_mass;
  std::printf("floored TOV -> 2D cylindrical [0,12]^2: 3D M0 %.8f, of it the atmosphere (rho <= %.1e) %.2e; matter outside %.2e; "
              "imported / 3D on the grid - 1 = %.1e; after the solve rho_max %.6e (TOV %.6e)\n",
              h.source_all.rest_mass, h.atmosphere_rho, floor_share, h.outside_fraction,
              h.imported.rest_mass / h.source_grid.rest_mass - 1, h.rho_c, data.star.at(0).rho);
  EXPECT_GT(floor_share, 0.03);  // what a grid around the star leaves out
  EXPECT_LT(h.outside_fraction, 1e-6);
  EXPECT_DOUBLE_EQ(h.atmosphere_rho, 2 * kFloor);  // twice the data's floor (above Atmosphere::rho_thr = 1e-10)
  EXPECT_NEAR(h.imported.rest_mass / h.source_grid.rest_mass, 1.0, 1e-13);
  EXPECT_NEAR(h.rho_c / data.star.at(0).rho, 1.0, 1e-2);
  // Every point counted (HandOff::atmosphere_density = 0, the rule before): "the grid cuts the star".
  const std::string e = handoff_test::message_of([&] { hand_off(data, {"HandOff::atmosphere_density=0"}); });
  EXPECT_NE(e.find("outside the grid"), std::string::npos) << e;
  EXPECT_NE(e.find("HandOff::atmosphere_density"), std::string::npos) << e;
}

// A grid that does cut the star is still an error, naming the matter's threshold.
TEST(HandOffEtkLayout, GridCuttingTheStarIsAnError) {
  const FlooredTov data;
  const std::string e = handoff_test::message_of([&] {
    hand_off(data, {"Grid::xmax=[6,6,6.283185307179586]", "Grid::ncells=[24,24,1]", "Grid::block_size=[8,8,1]"});
  });
  EXPECT_NE(e.find("the grid cuts the star"), std::string::npos) << e;
  EXPECT_NE(e.find("rho > "), std::string::npos) << e;
}

// Data without ADMBase::gxx..gzz give no sqrt(gamma): the densitised D = rho W misses psi^6 (rho_c
// 40 % low after the solve), so XCFC::initial_metric = from_primitives keeps the data's rho and
// iterates psi with it (an error before: only from_conserved was allowed). With the metric in the
// data from_primitives stays an error (the conserved variables are imported).
TEST(HandOffEtkLayout, DataWithoutMetricFromPrimitives) {
  const FlooredTov data(false);
  const double rho_tov = data.star.at(0).rho;
  const handoff::HandOffReport a = hand_off(data, {"XCFC::initial_metric=from_primitives"});
  const handoff::HandOffReport b = hand_off(data, {});
  std::printf("TOV without the metric -> 2D cylindrical: rho_max after the solve / TOV - 1: from_primitives %+.2e, "
              "from_conserved (flat sqrt(gamma)) %+.2e; M0 (x2, z mirror) from_primitives %.6f\n",
              a.rho_c / rho_tov - 1, b.rho_c / rho_tov - 1, 2 * a.after.rest_mass);
  EXPECT_NEAR(a.rho_c / rho_tov, 1.0, 1e-2);
  EXPECT_LT(b.rho_c / rho_tov, 0.7);
  const FlooredTov with_metric;
  const std::string e = handoff_test::message_of([&] { hand_off(with_metric, {"XCFC::initial_metric=from_primitives"}); });
  EXPECT_NE(e.find("XCFC::initial_metric must be from_conserved"), std::string::npos) << e;
  EXPECT_NE(e.find("ADMBase::gxx"), std::string::npos) << e;
}

}  // namespace
