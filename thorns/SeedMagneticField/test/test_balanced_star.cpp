// SeedMagneticField::balance = hydrostatic: the seeded poloidal BU0 star after one short step. The
// velocity after a step dt from rest is dt times the acceleration at t = 0, so the rest-mass-weighted
// RMS velocity measures the residual of the momentum right-hand side: the unbalanced field's Lorentz
// force (balance: none) against what remains with the balanced fluid, the field unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/driver.hpp"
#include "remnant/vars/HydroBase.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

// The magnetised TOV parfile's physics on a coarse 2D cylindrical grid (dx = 0.5, no refinement), in
// the TOV star's fixed metric (the metric the balance assumes).
const std::string kStar = R"(
active_thorns: [Grid, MoL, Spacetime, EOS, Atmosphere, Con2Prim, HydroBase, GRMHD, TOV, SeedMagneticField, Analysis]
Grid: {coordinates: cylindrical, dimension: 2, ncells: [32, 32, 1], block_size: [16, 16, 1], xmin: [0, 0, 0],
       xmax: [16, 16, 6.283185307179586], ghost_zones: 3, boundary_lower: [axis, reflect, outflow],
       boundary_upper: [outflow, outflow, outflow]}
MoL: {method: rk3, dt: 0.5, final_time: 0.5}
EOS: {type: ideal_gas, gamma: 2.0, T_max: 1.0e6}
Atmosphere: {rho_thr: 1.0e-10, poly_K: 100.0, poly_gamma: 2.0}
HydroBase: {magnetic_field: evolved}
GRMHD: {reconstruction: ppm_ep, emf_reconstruction: ppm_ep, metric_face_interpolation: cubic, well_balanced: isentropic}
TOV: {eos_slice: polytrope, poly_K: 100.0, poly_gamma: 2.0, rho_central: 1.28e-3}
SeedMagneticField: {type: poloidal, B_max_gauss: 1.0e16}
Analysis: {every: 1}
)";
// With it the metric is re-solved from the (balanced) matter and the field's energy: the parfiles' xCFC.
const std::vector<std::string> kXcfc = {"active_thorns+=[XCFC]", "XCFC::solve_every=1", "XCFC::tolerance=1e-8",
                                         "XCFC::tolerance_initial=1e-10", "XCFC::initial_metric=from_conserved"};

struct Residual {
  std::vector<double> dm, v1, v2, R, z;  // rest mass, velocity and position of the star's cells after one step
  double divB_max = 0.0;
  double E_mag = 0.0;
};

Residual one_step(std::vector<std::string> overrides, bool xcfc = false) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = "balanced_star.yaml";
  o.parfile_text = &kStar;
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() / ("remnant_balanced_star_" + std::to_string(::getpid()));
  o.overrides = std::move(overrides);
  if (xcfc) o.overrides.insert(o.overrides.begin(), kXcfc.begin(), kXcfc.end());
  o.overrides.push_back("Flesh::out_dir=" + out.string());
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  Context& ctx = sim.context();
  Residual r;
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const double rho = prim.rho(i, j, k);
      if (rho < 1e-6) return;  // the star, not its surface layers
      r.dm.push_back(rho * b->cell_volume(i, j, k));
      r.v1.push_back(prim.vel1(i, j, k));
      r.v2.push_back(prim.vel2(i, j, k));
      const Point3 x = cell_point(*b, i, j, k);
      r.R.push_back(x[0]), r.z.push_back(x[1]);
    });
  }
  const auto& rows = ctx.service<analysis::History>("Analysis::history").rows;
  r.divB_max = rows.back().magnetic->divB_max;
  r.E_mag = rows.back().magnetic->E_mag;
  return r;
}

// Rest-mass-weighted RMS of |v_a - v_b| (the same grid and cells in both runs).
double rms_difference(const Residual& a, const Residual& b) {
  EXPECT_EQ(a.dm.size(), b.dm.size());
  double m = 0.0, mv2 = 0.0;
  for (std::size_t c = 0; c < a.dm.size() && c < b.dm.size(); ++c) {
    const double d1 = a.v1[c] - b.v1[c], d2 = a.v2[c] - b.v2[c];
    m += a.dm[c], mv2 += a.dm[c] * (d1 * d1 + d2 * d2);
  }
  return std::sqrt(mv2 / m);
}

// The same for the polar (theta) component only: no radial (l = 0) motion in it.
double rms_polar_difference(const Residual& a, const Residual& b) {
  double m = 0.0, mv2 = 0.0;
  for (std::size_t c = 0; c < a.dm.size() && c < b.dm.size(); ++c) {
    const double d1 = a.v1[c] - b.v1[c], d2 = a.v2[c] - b.v2[c], r = std::hypot(a.R[c], a.z[c]);
    const double vt = (d1 * a.z[c] - d2 * a.R[c]) / r;
    m += a.dm[c], mv2 += a.dm[c] * vt * vt;
  }
  return std::sqrt(mv2 / m);
}

TEST(BalancedStar, HydrostaticBalanceCutsTheInitialAcceleration) {
  // The unmagnetised star's own residual (truncation at dx = 0.5, the surface) is larger than the
  // field's force and the same in all runs: it is subtracted with a 1e14 G run, whose Lorentz force is
  // 1e-4 of the 1e16 G one. Measured (32^2, dt 0.5): rms 1.38e-7 -> 1.54e-8 (ratio 9.0), polar part
  // 9.37e-8 -> 8.70e-9.
  const Residual weak = one_step({"SeedMagneticField::balance=none", "SeedMagneticField::B_max_gauss=1e14"});
  const Residual none = one_step({"SeedMagneticField::balance=none"});
  const Residual balanced = one_step({"SeedMagneticField::balance=hydrostatic"});
  const double r_none = rms_difference(none, weak), r_bal = rms_difference(balanced, weak);
  const double t_none = rms_polar_difference(none, weak), t_bal = rms_polar_difference(balanced, weak);
  std::printf("fixed TOV metric: rms |v - v(1e14 G)| after one step (dt 0.5): balance none %.4e, hydrostatic %.4e "
              "(ratio %.3g); polar part %.4e, %.4e; E_mag %.6e vs %.6e; divB_max %.2e %.2e\n",
              r_none, r_bal, r_none / r_bal, t_none, t_bal, none.E_mag, balanced.E_mag, none.divB_max, balanced.divB_max);
  EXPECT_LT(r_bal, r_none / 5.0);
  EXPECT_LT(t_bal, t_none / 5.0);
  EXPECT_LT(balanced.divB_max, 1e-12);
  EXPECT_NEAR(balanced.E_mag / none.E_mag, 1.0, 1e-6);  // the same field and metric (one step apart)
}

// With the xCFC metric re-solved from the balanced matter the balance is NOT kept: the change of alpha
// that the perturbation (and the field's energy) makes is of the order of the Lorentz force itself and
// the balance does not include it (README, Balance). Measured (32^2): rms 1.34e-7 -> 3.27e-7 (the
// l = 0 part: the perturbation's monopole changes the star's mass), polar part 9.23e-8 -> 6.73e-8.
TEST(BalancedStar, XcfcMetricBackReactionIsNotBalanced) {
  const Residual weak = one_step({"SeedMagneticField::balance=none", "SeedMagneticField::B_max_gauss=1e14"}, true);
  const Residual none = one_step({"SeedMagneticField::balance=none"}, true);
  const Residual balanced = one_step({"SeedMagneticField::balance=hydrostatic"}, true);
  const double r_none = rms_difference(none, weak), r_bal = rms_difference(balanced, weak);
  const double t_none = rms_polar_difference(none, weak), t_bal = rms_polar_difference(balanced, weak);
  std::printf("xCFC metric: rms |v - v(1e14 G)| after one step: balance none %.4e, hydrostatic %.4e; polar part %.4e, %.4e; "
              "divB_max %.2e\n",
              r_none, r_bal, t_none, t_bal, balanced.divB_max);
  EXPECT_LT(t_bal, 0.85 * t_none);  // only the polar (non-radial) part falls, by ~27 %
  EXPECT_GT(r_bal, r_none);         // the record of the missing back-reaction: fails once it is included
  EXPECT_LT(balanced.divB_max, 1e-12);
}

void expect_input_error(std::vector<std::string> overrides, std::vector<std::string> fragments) {
  try {
    one_step(std::move(overrides));
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << msg << "\nmissing: " << f;
  }
}

TEST(BalancedStar, BadInputStopsBeforeTheFirstStep) {
  expect_input_error({"SeedMagneticField::balance=hydrostatic", "SeedMagneticField::type=toroidal",
                      "Grid::axial_vector_reflection=[mirror,opposite,mirror]"},
                     {"balances a poloidal field", "SeedMagneticField::type = toroidal"});
  expect_input_error({"SeedMagneticField::balance=hydrostatic", "SeedMagneticField::type=poloidal_and_toroidal",
                      "Grid::xmin=[0,-16,0]", "Grid::ncells=[32,64,1]", "Grid::boundary_lower=[axis,outflow,outflow]"},
                     {"balances a poloidal field", "SeedMagneticField::type = poloidal_and_toroidal"});
  expect_input_error({"SeedMagneticField::balance=hydrostatic", "EOS::type=polytrope", "GRMHD::well_balanced=none"},
                     {"EOS::type = ideal_gas", "polytrope"});
}

}  // namespace
