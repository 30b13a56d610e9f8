// The thorn's report of its model (issue 17, deliverable 2): the global quantities go to the log
// (one INFO line, `name = value`) and to <out_dir>/rotating_star.tsv (a header and one row), with the
// names the issue asks for, and they are the solver's numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "RotatingStar/report.hpp"
#include "RotatingStar/rns_solver.hpp"
#include "TOV/cold_slice.hpp"
#include "parfile_run.hpp"

namespace {

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string f; std::getline(s, f, '\t');) out.push_back(f);
  return out;
}

TEST(RotatingStarThorn, GlobalQuantitiesGoToTheLogAndTheTsv) {
  // The paper's magnetized-DRNS on a coarse single-level grid, the solver at nr = 200, no step.
  testing::internal::CaptureStdout();
  std::vector<std::string> tsv;
  {
    remnant::rotstar::test::ParfileRun run(
        "magnetized_drns.yaml", "rotreport",
        {"Grid::ncells=[32,64,1]", "Grid::max_level=0", "Grid::regions=[]", "Grid::region_levels=[]", "Grid::region_modes=[]",
         "Grid::region_bounds=[]", "RotatingStar::nr=200", "MoL::max_iterations=0", "MoL::final_time=-1", "IO::hdf5_every_time=0"});
    std::ifstream in(run.out_dir() / "rotating_star.tsv");
    for (std::string line; std::getline(in, line);) tsv.push_back(line);
  }
  const std::string log = testing::internal::GetCapturedStdout();
  ASSERT_EQ(tsv.size(), 2u) << "rotating_star.tsv: a header and one row";
  const auto names = split_tabs(tsv[0]), values = split_tabs(tsv[1]);
  ASSERT_EQ(names.size(), values.size());

  const auto slice = remnant::tov::polytrope_slice(100.0, 2.0, 0.5);
  remnant::rotstar::RnsParameters p = remnant::rotstar::test::drns_parameters();
  p.field.K_m = 3;
  p.field.m = 1;
  p.nr = 200;
  const auto rows = remnant::rotstar::global_rows(remnant::rotstar::RotatingStarModel(*slice, p).globals());
  ASSERT_EQ(names.size(), rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(names[k], rows[k].first);
    EXPECT_NEAR(std::stod(values[k]), rows[k].second, 1e-10 * std::abs(rows[k].second)) << rows[k].first;
    EXPECT_NE(log.find(" " + rows[k].first + " = "), std::string::npos) << rows[k].first << " is not in the log";
  }
  // The list: Komar, rest and proper mass, J, T/|W|, the magnetic energy ratio, equatorial
  // coordinate and circumferential radius, axis ratio, Omega_c, Omega_eq, B_max in Gauss, GRV2/GRV3.
  for (const char* want : {"M_komar", "M_rest", "M_proper", "J", "T_over_W", "H_over_W", "r_e", "R_circ", "axis_ratio", "Omega_c",
                           "Omega_e", "B_max_gauss", "GRV2", "GRV3"})
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  const std::size_t b = std::find(names.begin(), names.end(), "B_max_gauss") - names.begin();
  EXPECT_NEAR(std::stod(values[b]), 5.2e17, 0.1e17);  // in Gauss
}

}  // namespace
