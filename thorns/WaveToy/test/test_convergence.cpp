// WaveToy through the whole chain (parfile, scheduler, grid, MoL, IO): second-order convergence
// of a plane wave in 1D, 2D and 3D, measured over three resolutions.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <span>

#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

double final_error_norm(int dim, int n, double final_time) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/wavetoy_1d.yaml";
  o.quiet = true;
  const std::string cells = dim == 1 ? "[" + std::to_string(n) + ",1,1]"
                            : dim == 2 ? "[" + std::to_string(n) + "," + std::to_string(n) + ",1]"
                                       : "[" + std::to_string(n) + "," + std::to_string(n) + "," + std::to_string(n) + "]";
  const std::string block = dim == 1 ? "[16,1,1]" : dim == 2 ? "[16,16,1]" : "[8,8,8]";
  const std::string k = dim == 1 ? "[1,0,0]" : dim == 2 ? "[1,1,0]" : "[1,1,1]";
  const auto out = std::filesystem::temp_directory_path() / ("remnant_wavetoy_" + std::to_string(::getpid()));
  o.overrides = {"Grid::dimension=" + std::to_string(dim), "Grid::ncells=" + cells, "Grid::block_size=" + block,
                 "WaveToy::wave_numbers=" + k, "MoL::final_time=" + std::to_string(final_time),
                 "IO::tsv_every=0", "WaveToy::error_every=1", "Flesh::out_dir=" + out.string()};
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  EXPECT_NEAR(sim.context().time(), final_time, 1e-14);
  return sim.grid()->reduce(sim.vars().find("WaveToy::wave_error"), 0, ReductionKind::norm2);
}

void expect_second_order(int dim, int n0, double final_time) {
  const double e1 = final_error_norm(dim, n0, final_time);
  const double e2 = final_error_norm(dim, 2 * n0, final_time);
  const double e3 = final_error_norm(dim, 4 * n0, final_time);
  const double p12 = std::log2(e1 / e2), p23 = std::log2(e2 / e3);
  std::printf("WaveToy %dD: L2 errors %.3e %.3e %.3e at n = %d, %d, %d; orders %.3f %.3f\n", dim, e1, e2, e3, n0,
              2 * n0, 4 * n0, p12, p23);
  EXPECT_NEAR(p12, 2.0, 0.1);
  EXPECT_NEAR(p23, 2.0, 0.1);
  EXPECT_LT(e3, 1e-2);  // the solution is actually close to the exact one
}

}  // namespace

TEST(WaveToyConvergence, SecondOrder1D) { expect_second_order(1, 32, 1.0); }
TEST(WaveToyConvergence, SecondOrder2D) { expect_second_order(2, 32, 0.5); }
TEST(WaveToyConvergence, SecondOrder3D) { expect_second_order(3, 16, 0.25); }
