// A static TOV star (BU0) evolved in each coordinate system with a fixed metric: the largest drift
// of the central density, max_t |rho_c(t)/rho_c(0) - 1|, is truncation error and converges at about
// second order with resolution (PPM is third order in smooth regions, the surface and the centre
// limit it to about second).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

struct Setup {
  const char* name;
  std::vector<std::string> overrides;  // besides the cells
  int dim;
  int block;
  double final_time;
};

std::string cells(int dim, int n) {
  const std::string s = std::to_string(n);
  return dim == 1 ? "[" + s + ",1,1]" : dim == 2 ? "[" + s + "," + s + ",1]" : "[" + s + "," + s + "," + s + "]";
}

// Returns max |rho_c / rho_c(0) - 1| and the relative rest-mass change; throws InputError when the
// Grid cannot make these coordinates.
std::pair<double, double> drift(const Setup& s, int n) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/bu0_cow.yaml";
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() / ("remnant_static_tov_" + std::to_string(::getpid()));
  o.overrides = s.overrides;
  o.overrides.push_back("Grid::ncells=" + cells(s.dim, n));
  o.overrides.push_back("Grid::block_size=" + cells(s.dim, s.block));
  o.overrides.push_back("MoL::final_time=" + std::to_string(s.final_time));
  o.overrides.push_back("Flesh::out_dir=" + out.string());
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  const auto& rows = sim.context().service<analysis::History>("Analysis::history").rows;
  double worst = 0;
  for (const auto& r : rows) worst = std::max(worst, std::abs(r.rho_c / rows.front().rho_c - 1));
  return {worst, rows.back().rest_mass / rows.front().rest_mass - 1};
}

void expect_second_order(const Setup& s, int n0, double max_drift_fine) {
  std::pair<double, double> d[3];
  try {
    d[0] = drift(s, n0);
  } catch (const InputError& e) {
    // Every coordinate system is supported: an input error here is a broken parfile, not a skip.
    FAIL() << s.name << ": the static-star parfile was refused: " << e.what();
  }
  d[1] = drift(s, 2 * n0);
  d[2] = drift(s, 4 * n0);
  const double p12 = std::log2(d[0].first / d[1].first), p23 = std::log2(d[1].first / d[2].first);
  std::printf("static TOV %s: max|rho_c/rho_c0 - 1| = %.3e %.3e %.3e at n = %d, %d, %d; orders %.2f %.2f; "
              "rest-mass change %.1e %.1e %.1e\n",
              s.name, d[0].first, d[1].first, d[2].first, n0, 2 * n0, 4 * n0, p12, p23, d[0].second, d[1].second,
              d[2].second);
  EXPECT_GT(p23, 1.5);
  EXPECT_GT(p12, 1.2);
  EXPECT_LT(d[2].first, max_drift_fine);
}

}  // namespace

TEST(StaticTOV, Spherical1D) {
  expect_second_order({"1D spherical", {"Grid::xmax=[16,3.141592653589793,6.283185307179586]"}, 1, 25, 150.0}, 200,
                      1e-3);
}

TEST(StaticTOV, Cylindrical2D) {
  expect_second_order({"2D cylindrical",
                       {"Grid::coordinates=cylindrical", "Grid::dimension=2", "Grid::xmin=[0,0,0]",
                        "Grid::xmax=[12,12,6.283185307179586]", "Grid::boundary_lower=[axis,reflect,outflow]"},
                       2, 8, 100.0},
                      16, 3e-3);
}

TEST(StaticTOV, Cartesian3DOctant) {
  expect_second_order({"3D Cartesian (octant)",
                       {"Grid::coordinates=cartesian", "Grid::dimension=3", "Grid::xmin=[0,0,0]", "Grid::xmax=[12,12,12]",
                        "Grid::boundary_lower=[reflect,reflect,reflect]", "MoL::cfl=0.3"},
                       3, 8, 40.0},
                      8, 1e-2);
}
