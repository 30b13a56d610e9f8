// Whole start-ups of the shipped parfiles (final time 0): the primitives on the grid are the
// problem's states; parameters a problem was not defined for stop the run naming the parameter.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <span>
#include <string>

#include "remnant/driver.hpp"
#include "remnant/vars/HydroBase.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

std::string out_dir(const std::string& tag) {
  return (std::filesystem::temp_directory_path() / ("remnant_mhdtests_" + std::to_string(::getpid()) + "_" + tag)).string();
}

struct StartedRun {
  std::unique_ptr<Simulation> sim;
  std::string dir;
};

StartedRun start(const std::string& parfile, std::vector<std::string> extra) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/" + parfile;
  o.quiet = true;
  StartedRun r;
  r.dir = out_dir(parfile);
  o.overrides = {"Flesh::out_dir=" + r.dir, "MoL::final_time=0", "IO::hdf5_every_time=0", "IO::tsv_every=0"};
  o.overrides.insert(o.overrides.end(), extra.begin(), extra.end());
  r.sim = std::make_unique<Simulation>(catalog, o, MPI_COMM_WORLD);
  r.sim->setup_output_and_grid();
  r.sim->run();
  return r;
}

std::string error_of(const std::string& parfile, std::vector<std::string> extra) {
  try {
    StartedRun r = start(parfile, std::move(extra));
    std::filesystem::remove_all(r.dir);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MHDTestsInitialData, BalsaraParfilesSetTheirStates) {
  const double left_p[5] = {1, 30, 1000, 0.1, 0.95}, right_rho[5] = {0.125, 1, 1, 1, 1};
  const double left_vx[5] = {0, 0, 0, 0.999, 0.4};
  for (int n = 1; n <= 5; ++n) {
    StartedRun r = start("mhd_shocktube_balsara" + std::to_string(n) + ".yaml", {"Grid::ncells=[200,1,1]", "Grid::block_size=[50,1,1]"});
    Context& ctx = r.sim->context();
    int left = 0, right = 0;
    for (Block* b : ctx.grid().local_blocks()) {
      const vars::HydroBase::prim prim(ctx, *b);
      for (int i = 0; i < b->n[0]; ++i) {
        if (b->x(0, i) < 0) {
          ++left;
          EXPECT_NEAR(prim.press(i, 0, 0), left_p[n - 1], 1e-12 * left_p[n - 1]) << "balsara" << n;
          EXPECT_DOUBLE_EQ(prim.vel(0, i, 0, 0), left_vx[n - 1]);
          EXPECT_NEAR(prim.W(i, 0, 0) * std::sqrt(1 - left_vx[n - 1] * left_vx[n - 1] -
                                                  (n == 5 ? 0.3 * 0.3 + 0.2 * 0.2 : 0.0)), 1.0, 1e-12);
        } else {
          ++right;
          EXPECT_DOUBLE_EQ(prim.rho(i, 0, 0), right_rho[n - 1]) << "balsara" << n;
        }
      }
    }
    // Face fields: uniform normal B^x, each cell's transverse field on its y and z faces.
    const double by_left[5] = {1, 6, 7, 7, 0.3}, by_right[5] = {-1, 0.7, 0.7, -7, -0.7}, bx[5] = {0.5, 5, 10, 10, 2};
    const int f1 = ctx.var("HydroBase::Bface1"), f2 = ctx.var("HydroBase::Bface2"), dv = ctx.var("MHDTests::divB");
    for (Block* b : ctx.grid().local_blocks()) {
      const Field B1 = b->field(f1, 0), B2 = b->field(f2, 0), div = b->field(dv, 0);
      for (int i = 0; i < b->n[0]; ++i) {
        EXPECT_EQ(B1(i, 0, 0), bx[n - 1]);
        EXPECT_EQ(B2(i, 0, 0), b->x(0, i) < 0 ? by_left[n - 1] : by_right[n - 1]) << "balsara" << n << " x " << b->x(0, i);
        EXPECT_EQ(div(i, 0, 0), 0.0);
      }
    }
    EXPECT_EQ(left, 100);
    EXPECT_EQ(right, 100);
    std::filesystem::remove_all(r.dir);
  }
}

TEST(MHDTestsInitialData, WrongAdiabaticIndexIsRefusedNamingEOSGamma) {
  const std::string e = error_of("mhd_shocktube_balsara1.yaml", {"EOS::gamma=1.6666666666666667"});
  EXPECT_NE(e.find("EOS::gamma = 2"), std::string::npos) << e;
  EXPECT_NE(e.find("balsara1"), std::string::npos) << e;
}

// The 2D parfiles start with div B at round-off: MHDTests::divB (the per-cell relative divergence)
// after the initial data, on the refined field-loop grid too.
TEST(MHDTestsInitialData, TwoDimensionalParfilesStartDivergenceFree) {
  for (const char* parfile : {"field_loop_2d.yaml", "blast_cylindrical_2d.yaml", "rotor_2d.yaml"}) {
    StartedRun r = start(parfile, {"Grid::ncells=[64,64,1]", "Grid::block_size=[16,16,1]"});
    Context& ctx = r.sim->context();
    const int dv = ctx.var("MHDTests::divB"), e = ctx.var("MHDTests::b2");
    const double div = ctx.grid().reduce(dv, 0, ReductionKind::maximum);
    const double energy = ctx.grid().reduce(e, 0, ReductionKind::volume_integral);
    std::printf("%s: divB_max %.2e, magnetic energy %.6e, %zu blocks\n", parfile, div, energy, ctx.grid().all_blocks().size());
    EXPECT_LE(div, 1e-13) << parfile;
    EXPECT_GT(energy, 0.0) << parfile;
    std::filesystem::remove_all(r.dir);
  }
}

TEST(MHDTestsInitialData, MissingProblemAndTwoDimensionalProblemOn1DGridAreRefused) {
  std::string e = error_of("mhd_shocktube_balsara2.yaml", {"MHDTests::problem=none"});
  EXPECT_NE(e.find("MHDTests::problem"), std::string::npos) << e;
  e = error_of("mhd_shocktube_balsara2.yaml", {"HydroBase::magnetic_field=none"});
  EXPECT_NE(e.find("HydroBase::magnetic_field = evolved"), std::string::npos) << e;
  e = error_of("mhd_shocktube_balsara2.yaml", {"MHDTests::problem=rotor"});
  EXPECT_NE(e.find("Grid::dimension"), std::string::npos) << e;
}
