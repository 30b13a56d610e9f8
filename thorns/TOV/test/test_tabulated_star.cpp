// The tabulated EOS through the whole chain (issue 20, item 4): a static star on the cold
// beta-equilibrium slice of the reduced SFHo table (TOV::eos_slice = tabulated_beta, rho_c = 1.4e-3,
// M = 1.54 baryonic), evolved with the same table (recovery through the eps -> T inversion) in
// Cowling and with xCFC solved every step, 1D spherical to r = 16.
// The star's initial data are consistent with the evolution's table interpolation (table_slice.cpp):
// Ye, eps and p of every cell are the table's own values at (rho, T_min), and H(rho) is integrated at
// third order between the table's density nodes (where the interpolated table has kinks). Before,
// TOV resampled the slice on 800 densities: a pulse from that interpolation error reached the
// centre at t ~ 9.6 with an amplitude that grew with resolution (max |rho_c/rho_c0 - 1| over
// t <= 20: 9.9e-4, 1.3e-3, 3.0e-3 at 200, 400, 800 cells; order 0.9 over t <= 6).
// Measured now (Cowling; xCFC within 3 %):
//   t <= 6 (the response to the initial truncation error): 6.14e-4, 1.82e-4, 5.27e-5: order 1.76, 1.78;
//   t <= 20 (with the first signal from the crust, t ~ 8.5): 6.17e-4, 2.21e-4, 1.03e-4: order 1.5, 1.1;
//   t <= 150 at 200, 400 cells: 2.33e-3, 4.6e-4. Not a convergence claim: from t ~ 27 a
//   disturbance from the crust (rho ~ 1e-4 .. 1e-6, r ~ 6) reaches the centre, and it grows with
//   resolution (4.7e-4 at 800, 3.9e-3 at 1600 cells); the kinks of the trilinear table at its
//   nodes also remain (see the issue). Bounds: measured orders less 0.2; amplitudes +50 %.
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
#include "remnant_test/shared_tables.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

struct Drift {
  double rho_c = 0, rho_c_6 = 0, rho_c_20 = 0, rest_mass = 0, budget = 0;  // max |rho_c/rho_c0 - 1| (t <= 6, 20)
};

Drift run(const char* parfile, int n, double final_time = 150) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/" + parfile;
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() / ("remnant_tab_star_" + std::to_string(::getpid()));
  o.overrides = {"EOS::type=tabulated",
                 "EOS::table_file=" + remnant::test::shared_eos("SFHo_reduced_39r_39t_20y.h5"),
                 "TOV::eos_slice=tabulated_beta",
                 "TOV::rho_central=1.4e-3",
                 "Grid::ncells=[" + std::to_string(n) + ",1,1]",
                 "Grid::block_size=[" + std::to_string(n / 8) + ",1,1]",
                 "Grid::xmax=[16,3.141592653589793,6.283185307179586]",
                 "MoL::final_time=" + std::to_string(final_time),
                 "Flesh::out_dir=" + out.string()};
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  const auto& rows = sim.context().service<analysis::History>("Analysis::history").rows;
  Drift d;
  for (const auto& r : rows) {
    const double drift = std::abs(r.rho_c / rows.front().rho_c - 1);
    d.rho_c = std::max(d.rho_c, drift);
    if (r.time <= 6) d.rho_c_6 = std::max(d.rho_c_6, drift);
    if (r.time <= 20) d.rho_c_20 = std::max(d.rho_c_20, drift);
    d.budget = std::max(d.budget, std::abs(r.mass_budget / rows.front().mass_budget - 1));
  }
  d.rest_mass = rows.back().rest_mass / rows.front().rest_mass - 1;
  std::filesystem::remove_all(out);
  return d;
}

double order(double coarse, double fine) { return std::log2(coarse / fine); }

void expect_star_holds(const char* parfile, const char* name, double max_drift_200, double max_drift_400) {
  const Drift a = run(parfile, 200), b = run(parfile, 400), c = run(parfile, 800, 20);
  std::printf("SFHo static star, %s: max|rho_c/rho_c0 - 1| = %.3e %.3e at 200, 400 cells (t <= 150); "
              "t <= 6: %.3e %.3e %.3e (orders %.2f %.2f); t <= 20: %.3e %.3e %.3e (orders %.2f %.2f) at 200, 400, "
              "800; rest mass %.1e %.1e; budget %.1e %.1e\n",
              name, a.rho_c, b.rho_c, a.rho_c_6, b.rho_c_6, c.rho_c_6, order(a.rho_c_6, b.rho_c_6),
              order(b.rho_c_6, c.rho_c_6), a.rho_c_20, b.rho_c_20, c.rho_c_20, order(a.rho_c_20, b.rho_c_20),
              order(b.rho_c_20, c.rho_c_20), a.rest_mass, b.rest_mass, a.budget, b.budget);
  EXPECT_GT(order(a.rho_c_6, b.rho_c_6), 1.55) << name;
  EXPECT_GT(order(b.rho_c_6, c.rho_c_6), 1.55) << name << ": the initial data must converge with the grid";
  EXPECT_GT(order(a.rho_c_20, b.rho_c_20), 1.3) << name;
  EXPECT_GT(order(b.rho_c_20, c.rho_c_20), 0.9) << name;
  EXPECT_LT(c.rho_c_20, 1.6e-4) << name;
  EXPECT_LT(a.rho_c, max_drift_200) << name;
  EXPECT_LT(b.rho_c, max_drift_400) << name;
  for (const Drift& d : {a, b}) {
    EXPECT_LT(std::abs(d.rest_mass), 2e-7) << name;
    EXPECT_LT(d.budget, 1e-12) << name;
  }
}

}  // namespace

TEST(TabulatedStaticStar, SFHoCowling) {
  REQUIRE_TABLE(remnant::test::shared_eos("SFHo_reduced_39r_39t_20y.h5"));
  expect_star_holds("bu0_cow.yaml", "Cowling", 3.5e-3, 7e-4);
}

TEST(TabulatedStaticStar, SFHoWithXCFC) {
  REQUIRE_TABLE(remnant::test::shared_eos("SFHo_reduced_39r_39t_20y.h5"));
  expect_star_holds("bu0_dyn.yaml", "xCFC every step", 3.5e-3, 7e-4);
}
