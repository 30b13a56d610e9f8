// The rest-mass budget (HydroBase::mass_budget, Analysis columns outflow, atmosphere_source,
// mass_budget): with matter leaving and entering through the outer boundaries and cells reset to
// atmosphere, rest_mass + outflow - atmosphere_source stays constant to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "history_run.hpp"

namespace {

using namespace remnant;

// A shock tube whose dense gas streams out through the left boundary (v = -0.3) and expands into an
// atmosphere on the right, whose cells the con2prim sweeps keep resetting.
std::vector<analysis::StarDiagnostics> run(const std::string& coords, int dim, const std::string& refinement = "") {
  std::ostringstream par;
  par << "active_thorns: [Grid, MoL, Spacetime, EOS, Atmosphere, Con2Prim, HydroBase, GRMHD, Analysis]\n"
         "Grid: {coordinates: " << coords << ", dimension: " << dim << ", ncells: [64, 16, 1], "
         "block_size: [16, 16, 1], xmin: [1, 0.5, 0], xmax: [2, 1.5, 1], ghost_zones: 3, "
         "boundary_lower: [outflow, outflow, outflow], boundary_upper: [outflow, outflow, outflow]"
      << refinement << "}\n"
         "MoL: {method: rk3, cfl: 0.4, max_iterations: 60}\n"
         "EOS: {type: ideal_gas, gamma: 1.6666666666666667, rho_max: 1.0e3, T_max: 1.0e7}\n"
         "Atmosphere: {rho_thr: 1.0e-6}\n"
         "GRMHD: {reconstruction: ppm, initial_data: shock_tube, shock_left: [10.0, -0.3, 0.0, 0.0, 13.33], "
         "shock_right: [1.0e-9, 0.0, 0.0, 0.0, 1.0e-12], shock_position: 1.4}\n"
         "Analysis: {every: 1}\n";
  return grmhd::test::run_parfile_history("budget", par.str());
}

void expect_budget_constant(const std::vector<analysis::StarDiagnostics>& rows, const char* what) {
  ASSERT_GT(rows.size(), 10u);
  const auto& a = rows.front();
  const auto& z = rows.back();
  double worst = 0;
  for (const auto& r : rows) worst = std::max(worst, std::abs(r.mass_budget / a.mass_budget - 1));
  std::printf("%s: rest mass %.15g -> %.15g (%.3e), outflow %.6e, atmosphere source %.6e, budget drift %.2e\n", what,
              a.rest_mass, z.rest_mass, z.rest_mass / a.rest_mass - 1, z.outflow, z.atmosphere_source, worst);
  EXPECT_GT(std::abs(z.rest_mass / a.rest_mass - 1), 1e-3) << "the test needs mass to leave the grid";
  EXPECT_NE(z.outflow, 0.0);
  // The atmosphere's share is far above round-off: without it the budget would drift visibly.
  EXPECT_GT(std::abs(z.atmosphere_source / a.rest_mass), 1e-10) << "the test needs atmosphere resets";
  EXPECT_LT(worst, 1e-13);
  EXPECT_DOUBLE_EQ(z.mass_budget, z.rest_mass + z.outflow - z.atmosphere_source);
}

}  // namespace

TEST(MassBudget, CartesianShockTubeKeepsTheBudgetToRoundOff) { expect_budget_constant(run("cartesian", 1), "cartesian 1D"); }

TEST(MassBudget, Cylindrical2DKeepsTheBudgetToRoundOff) { expect_budget_constant(run("cylindrical", 2), "cylindrical 2D"); }

// A refined level on the boundary where the mass leaves (and on the lower and upper z faces): the
// boundary faces of level-1 blocks count, the coarse-fine faces (refluxed) cancel.
TEST(MassBudget, RefinedBoundaryKeepsTheBudgetToRoundOff) {
  expect_budget_constant(run("cylindrical", 2, ", max_level: 1, regions: [box], region_levels: [1], "
                                               "region_bounds: [0.9, 1.3, 0.4, 1.6, -1, 2]"),
                         "cylindrical 2D, level 1 at the left boundary");
}
