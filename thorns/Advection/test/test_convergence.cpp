// Advection through the whole chain on refined meshes in every coordinate system: second-order
// convergence of the L1 error across static and moving refinement boundaries, and the total
// content conserved to round-off (refluxing, conservative prolongation and restriction).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>

#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

struct Run {
  double error = 0;         // L1 norm of u - exact at the final time
  double conservation = 0;  // |total(end) - total(0)| / total(0)
  int finest = 0;
};

// The first and last values of a TSV time series.
std::pair<double, double> first_last(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  double first = NAN, last = NAN;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    double it, t, v;
    s >> it >> t >> v;
    if (std::isnan(first)) first = v;
    last = v;
  }
  return {first, last};
}

Run run(const std::string& parfile, int scale, std::vector<std::string> extra) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/" + parfile;
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() /
                   ("remnant_advection_" + std::to_string(::getpid()) + "_" + std::to_string(scale));
  o.overrides = {"Flesh::out_dir=" + out.string(), "IO::tsv_every=1", "IO::tsv_variables=[\"Advection::u\"]",
                 "IO::tsv_reductions=[volume_integral]", "Advection::error_every=1"};
  for (auto& e : extra) o.overrides.push_back(e);
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  Run r;
  r.error = sim.grid()->reduce(sim.vars().find("Advection::u_error"), 0, ReductionKind::norm1);
  const auto [first, last] = first_last((out / "Advection-u.u.volume_integral.tsv").string());
  r.conservation = std::abs(last - first) / std::abs(first);
  for (const auto& k : sim.grid()->all_blocks()) r.finest = std::max(r.finest, k.level);
  std::filesystem::remove_all(out);
  return r;
}

// Resolutions n0, 2 n0, 4 n0 with blocks scaled alike, so that the refined regions cover the
// same coordinates at every resolution.
void expect_second_order(const std::string& parfile, std::array<int, 3> n0, std::array<int, 3> b0, int dim,
                         double min_order, std::vector<std::string> extra = {}) {
  double e[3];
  for (int s = 0; s < 3; ++s) {
    const int f = 1 << s;
    auto triple = [&](const std::array<int, 3>& a) {
      std::ostringstream o;
      o << "[" << (dim > 0 ? a[0] * f : 1) << "," << (dim > 1 ? a[1] * f : 1) << "," << (dim > 2 ? a[2] * f : 1) << "]";
      return o.str();
    };
    std::vector<std::string> args = {"Grid::ncells=" + triple(n0), "Grid::block_size=" + triple(b0)};
    args.insert(args.end(), extra.begin(), extra.end());
    const Run r = run(parfile, f, args);
    e[s] = r.error;
    std::printf("%s: n0 x %d: L1 error %.4e, conservation %.2e, finest level %d\n", parfile.c_str(), f, r.error,
                r.conservation, r.finest);
    EXPECT_LT(r.conservation, 1e-13) << parfile << " at scale " << f;
    EXPECT_GE(r.finest, 1) << "the run must actually be refined";
  }
  const double p1 = std::log2(e[0] / e[1]), p2 = std::log2(e[1] / e[2]);
  std::printf("%s: convergence orders %.3f %.3f\n", parfile.c_str(), p1, p2);
  EXPECT_GT(p2, min_order) << parfile;
  EXPECT_GT(p1, min_order - 0.3) << parfile;
}

}  // namespace

TEST(AdvectionConvergence, Cartesian2D) { expect_second_order("advection_cartesian_2d.yaml", {16, 16, 1}, {4, 4, 1}, 2, 1.8); }
TEST(AdvectionConvergence, Cylindrical2D) { expect_second_order("advection_cylindrical_2d.yaml", {8, 16, 1}, {4, 4, 1}, 2, 1.8); }
TEST(AdvectionConvergence, Spherical1D) { expect_second_order("advection_spherical_1d.yaml", {32, 1, 1}, {4, 1, 1}, 1, 1.8); }
// The bump passes close to the origin, where the theta speed limits the step: a shorter run.
TEST(AdvectionConvergence, Spherical2D) {
  expect_second_order("advection_spherical_2d.yaml", {16, 16, 1}, {4, 4, 1}, 2, 1.8, {"MoL::final_time=0.15"});
}
