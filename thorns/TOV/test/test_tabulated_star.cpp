// The tabulated EOS through the whole chain (issue 20, item 4): a static star on the cold
// beta-equilibrium slice of the reduced SFHo table (TOV::eos_slice = tabulated_beta, rho_c = 1.4e-3,
// M = 1.54 baryonic), evolved with the same table (recovery through the eps -> T inversion) in
// Cowling and with xCFC solved every step, 1D spherical, 200 and 400 cells to r = 16, t = 150
// (about two F periods).
// Measured max |rho_c / rho_c(0) - 1|: Cowling 2.35e-3, 1.28e-3; xCFC 1.76e-3, 1.25e-3; rest mass
// changes by < 6e-8 and its budget holds to 1e-13. The drift decreases with resolution but not yet
// at second order (orders 0.9 and 0.5; at 800 cells a pulse of 3e-3 at t ~ 10 keeps the Cowling
// maximum at 3.0e-3): the bounds below are the measured values with a 50 % margin, not a
// convergence claim. Most of the floor is the initial data: TOV samples the cold slice at 800
// densities (slice_from_parameters.cpp); with 8000 the Cowling maximum is 2.3e-3, 4.5e-4, 4.7e-4
// at 200, 400, 800 cells (32000: the same), and these bounds still hold.
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
  double rho_c = 0, rest_mass = 0, budget = 0;
};

Drift run(const char* parfile, int n) {
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
                 "MoL::final_time=150",
                 "Flesh::out_dir=" + out.string()};
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  const auto& rows = sim.context().service<analysis::History>("Analysis::history").rows;
  Drift d;
  for (const auto& r : rows) {
    d.rho_c = std::max(d.rho_c, std::abs(r.rho_c / rows.front().rho_c - 1));
    d.budget = std::max(d.budget, std::abs(r.mass_budget / rows.front().mass_budget - 1));
  }
  d.rest_mass = rows.back().rest_mass / rows.front().rest_mass - 1;
  std::filesystem::remove_all(out);
  return d;
}

void expect_star_holds(const char* parfile, const char* name, double max_drift_200, double max_drift_400) {
  const Drift a = run(parfile, 200), b = run(parfile, 400);
  std::printf("SFHo static star, %s: max|rho_c/rho_c0 - 1| = %.3e %.3e at 200, 400 cells; rest mass %.1e %.1e; "
              "budget %.1e %.1e\n",
              name, a.rho_c, b.rho_c, a.rest_mass, b.rest_mass, a.budget, b.budget);
  EXPECT_LT(a.rho_c, max_drift_200) << name;
  EXPECT_LT(b.rho_c, max_drift_400) << name;
  EXPECT_LT(b.rho_c, a.rho_c) << name << ": the drift must fall with resolution";
  for (const Drift& d : {a, b}) {
    EXPECT_LT(std::abs(d.rest_mass), 2e-7) << name;
    EXPECT_LT(d.budget, 1e-12) << name;
  }
}

}  // namespace

TEST(TabulatedStaticStar, SFHoCowling) {
  REQUIRE_TABLE(remnant::test::shared_eos("SFHo_reduced_39r_39t_20y.h5"));
  expect_star_holds("bu0_cow.yaml", "Cowling", 3.5e-3, 2e-3);
}

TEST(TabulatedStaticStar, SFHoWithXCFC) {
  REQUIRE_TABLE(remnant::test::shared_eos("SFHo_reduced_39r_39t_20y.h5"));
  expect_star_holds("bu0_dyn.yaml", "xCFC every step", 2.7e-3, 1.9e-3);
}
