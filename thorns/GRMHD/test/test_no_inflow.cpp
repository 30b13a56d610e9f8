// HydroBase::outflow_boundary = no_inflow at the Grid's outflow faces: a uniform flow that enters
// through the upper x face and leaves through the lower one. zero_gradient lets the flow in
// unchanged (the rest mass stays constant: what enters replaces what leaves); no_inflow stops the
// inflow driven by the ghosts' inward velocity, so that the domain drains. Matter that leaves
// through both faces is untouched by the option (bit-identical histories).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "history_run.hpp"

namespace {

using namespace remnant;

// Gas at rest-mass density 1 (left) and `rho_right` moving with v_left, v_right along x.
std::vector<analysis::StarDiagnostics> run(const std::string& coords, int dim, const std::string& boundary,
                                           double v_left, double v_right, double rho_right = 1.0,
                                           bool field = false) {
  std::ostringstream par;
  par << "active_thorns: [Grid, MoL, Spacetime, EOS, Atmosphere, Con2Prim, HydroBase, GRMHD, Analysis]\n"
         "Grid: {coordinates: " << coords << ", dimension: " << dim << ", ncells: [64, 8, 1], "
         "block_size: [16, 8, 1], xmin: [1, 0.5, 0], xmax: [2, 1.5, 1], ghost_zones: 3, "
         "boundary_lower: [outflow, outflow, outflow], boundary_upper: [outflow, outflow, outflow]}\n"
         "MoL: {method: rk3, cfl: 0.4, max_iterations: 80}\n"
         "EOS: {type: ideal_gas, gamma: 1.6666666666666667, rho_max: 1.0e3, T_max: 1.0e7}\n"
         "Atmosphere: {rho_thr: 1.0e-9}\n"
         "HydroBase: {outflow_boundary: " << boundary << (field ? ", magnetic_field: evolved" : "") << "}\n"
         "GRMHD: {reconstruction: ppm, initial_data: shock_tube, shock_left: [1.0, " << v_left
      << ", 0.0, 0.0, 0.1], shock_right: [" << rho_right << ", " << v_right
      << ", 0.0, 0.0, 0.1], shock_position: 1.5"
      << (field ? ", shock_field_left: [0.3, 0.4, 0.0], shock_field_right: [0.3, 0.4, 0.0]" : "") << "}\n"
         "Analysis: {every: 1}\n";
  return grmhd::test::run_parfile_history("noinflow", par.str());
}

void report(const std::vector<analysis::StarDiagnostics>& rows, const char* what) {
  const auto& a = rows.front();
  const auto& z = rows.back();
  std::printf("%s: t %.4f rest mass %.15g -> %.15g (%.3e), outflow %.6e, budget %.3e\n", what, z.time, a.rest_mass,
              z.rest_mass, z.rest_mass / a.rest_mass - 1, z.outflow, z.mass_budget / a.mass_budget - 1);
}

// Uniform flow at v = -0.5 along Cartesian x: in through the upper face, out through the lower one.
TEST(NoInflow, CartesianUniformInflowIsStopped) {
  const auto zg = run("cartesian", 1, "zero_gradient", -0.5, -0.5);
  const auto ni = run("cartesian", 1, "no_inflow", -0.5, -0.5);
  ASSERT_GT(zg.size(), 10u);
  ASSERT_EQ(zg.size(), ni.size());
  report(zg, "cartesian zero_gradient");
  report(ni, "cartesian no_inflow");
  const auto &a = zg.front(), &z = zg.back(), &n = ni.back();
  // zero_gradient: the inflow replaces the outflow, the rest mass stays.
  EXPECT_LT(std::abs(z.rest_mass / a.rest_mass - 1), 1e-12);
  // The same uniform state leaves through the lower face in both runs (the upper face's
  // disturbance travels at (v - c_s) / (1 - v c_s) = -0.73 and does not get there by t = 0.7):
  // rho W |v| t per unit length. What no_inflow still lets in is the Riemann fan of interior gas
  // moving away from ghosts at rest: about 1 % of zero_gradient's inflow here.
  const double lower = a.rest_mass * 0.5 * n.time;
  const double entered_ni = n.outflow - lower, entered_zg = z.outflow - lower;  // < 0: entered
  std::printf("zero_gradient let in %.4e of the mass, no_inflow %.4e (%.2f %% of it)\n", -entered_zg / a.rest_mass,
              -entered_ni / a.rest_mass, 100 * entered_ni / entered_zg);
  EXPECT_LT(entered_zg, -0.3 * a.rest_mass);
  EXPECT_LT(entered_ni / entered_zg, 0.02);
  for (const auto* r : {&zg, &ni}) EXPECT_LT(std::abs(r->back().mass_budget / r->front().mass_budget - 1), 1e-13);
}

// With a magnetic field (B^x = 0.3, B^y = 0.4; the MHD fluxes and EMFs read the same ghosts): the
// same drain, about 1 % of zero_gradient's inflow still drawn in.
TEST(NoInflow, MagnetisedUniformInflowIsStopped) {
  const auto zg = run("cartesian", 1, "zero_gradient", -0.5, -0.5, 1.0, true);
  const auto ni = run("cartesian", 1, "no_inflow", -0.5, -0.5, 1.0, true);
  report(zg, "magnetised zero_gradient");
  report(ni, "magnetised no_inflow");
  const auto &a = zg.front(), &z = zg.back(), &n = ni.back();
  EXPECT_LT(std::abs(z.rest_mass / a.rest_mass - 1), 1e-12);
  const double lower = a.rest_mass * 0.5 * n.time;
  const double entered_ni = n.outflow - lower, entered_zg = z.outflow - lower;
  std::printf("magnetised: zero_gradient let in %.4e, no_inflow %.4e (%.2f %%)\n", -entered_zg / a.rest_mass,
              -entered_ni / a.rest_mass, 100 * entered_ni / entered_zg);
  EXPECT_LT(entered_zg, -0.3 * a.rest_mass);
  EXPECT_LT(entered_ni / entered_zg, 0.02);
  EXPECT_LT(std::abs(n.mass_budget / ni.front().mass_budget - 1), 1e-13);
}

// The same in cylindrical R (2D): zero_gradient takes in more through R = 2 than leaves through
// R = 1, no_inflow drains the domain; the outflow column shows the difference, the budget closes.
TEST(NoInflow, Cylindrical2DUniformInflowIsStopped) {
  const auto zg = run("cylindrical", 2, "zero_gradient", -0.5, -0.5);
  const auto ni = run("cylindrical", 2, "no_inflow", -0.5, -0.5);
  report(zg, "cylindrical zero_gradient");
  report(ni, "cylindrical no_inflow");
  const auto &a = zg.front(), &z = zg.back(), &n = ni.back();
  EXPECT_LT(z.outflow, -0.2 * a.rest_mass);  // net inflow
  EXPECT_GT(n.outflow, 0.2 * a.rest_mass);   // net outflow
  EXPECT_LT(n.rest_mass, 0.8 * a.rest_mass);
  for (const auto* r : {&zg, &ni}) EXPECT_LT(std::abs(r->back().mass_budget / r->front().mass_budget - 1), 1e-13);
}

}  // namespace

// Gas leaving through both faces: the diode never acts, the histories agree to the bit.
TEST(NoInflow, OutgoingFlowIsUnchanged) {
  const auto zg = run("cylindrical", 2, "zero_gradient", -0.3, 0.3, 0.5);
  const auto ni = run("cylindrical", 2, "no_inflow", -0.3, 0.3, 0.5);
  report(zg, "outgoing zero_gradient");
  report(ni, "outgoing no_inflow");
  ASSERT_EQ(zg.size(), ni.size());
  EXPECT_GT(zg.back().outflow, 1e-2 * zg.front().rest_mass);
  for (std::size_t i = 0; i < zg.size(); ++i) {
    EXPECT_EQ(zg[i].rest_mass, ni[i].rest_mass) << "row " << i;
    EXPECT_EQ(zg[i].outflow, ni[i].outflow) << "row " << i;
  }
}

// An unknown keyword is refused with the parameter's name and the allowed values.
TEST(NoInflow, UnknownKeywordIsAnInputError) {
  try {
    run("cartesian", 1, "diode", -0.5, -0.5);
    FAIL() << "expected an input error";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    std::printf("%s\n", what.c_str());
    EXPECT_NE(what.find("outflow_boundary"), std::string::npos);
    EXPECT_NE(what.find("no_inflow"), std::string::npos);
  }
}
