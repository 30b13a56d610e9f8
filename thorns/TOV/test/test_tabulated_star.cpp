// The tabulated EOS through the whole chain (issue 20, item 4): a static star on the cold
// beta-equilibrium slice of the reduced SFHo table (TOV::eos_slice = tabulated_beta, rho_c = 1.4e-3,
// M = 1.54 baryonic), evolved with the same table (recovery through the eps -> T inversion) in
// Cowling and with xCFC solved every step, 1D spherical to r = 16.
// The table is interpolated linearly in (ln rho, ln T, Ye), so the star's rho(r) and Ye(r) have kinks
// where rho crosses a density node and where beta-equilibrium Ye crosses a Ye node (38 in the star);
// p(r) is smooth there. Two things made those kinks push on the star, each with an O(1) force in the
// kink's cells that did not shrink with the grid (first-step |dS/dt|/D at the node rho = 5.9e-4:
// 5.3e-4, 3.7e-4, 2.9e-4 at 400, 800, 1600 cells):
//  - the initial data: ln rho(H) was a monotone spline between density nodes, whose end derivatives
//    are first order and which smoothed the Ye-node kinks: dp/dH = e + p was off by 0.3 % at nodes,
//    16 % at Ye crossings (ColdSliceIsBalancedAtTheTableKinks: 5.8e-8 now, table_slice.hpp);
//  - the face pressure: p(rho_face, T_face, Ye_face) from kinked rho and Ye is off by O(dx) at a kink;
//    GRMHD now reconstructs p for a table (face_thermo.hpp). Each fix alone leaves the O(1) force:
//    with the balanced slice and p(rho_face, T_face, Ye_face), t <= 25 gives 6.17e-4, 2.20e-4, 9.8e-5
//    (orders 1.49, 1.16), which SFHoCowling refuses; the slice alone is checked by
//    ColdSliceIsBalancedAtTheTableKinks.
// max |rho_c/rho_c0 - 1| at 200, 400, 800 (1600) cells, Cowling (xCFC within 5 %):
//   before: t <= 6: 6.14e-4, 1.82e-4, 5.27e-5; t <= 25: 6.17e-4, 2.21e-4, 1.03e-4 (4.6e-5; orders 1.5,
//     1.1, 1.2: pulses from the nodes); t <= 60: 2.33e-3, 4.59e-4, 4.84e-4, 3.92e-3.
//   now:    t <= 6: 6.33e-4, 1.86e-4, 5.39e-5 (1.46e-5): orders 1.76, 1.79, 1.88;
//           t <= 25: 6.51e-4, 1.91e-4, 5.54e-5 (3.1e-5): orders 1.77, 1.78 (0.8 at 1600: a pulse at
//           t ~ 9); t <= 150 at 200, 400: 1.45e-3, 5.5e-4.
// Over 1 ms with EOS::table_repair_thermal_index and a mass-weighted norm the drift converges:
// test_tabulated_drift.cpp. The history of why rho_c does not, with the table as is:
// Not converging (not asserted), t <= 60 at 200, 400, 800, 1600 cells: Cowling 1.45e-3, 5.5e-4,
// 8.1e-4, 4.6e-3; xCFC 1.43e-3, 6.5e-4, 8.6e-4, 5.4e-3: from t ~ 27 a step from the crust (r ~ 5 .. 6)
// focused at the centre. Cause (Cowling, t <= 60 at 400 / 800 / 1600 cells, tabstar2 experiments):
//  - one node of the table: (rho, T, Ye) = (1.377e-4, T_min = 0.1 MeV, 0.0721), at the crust-core
//    transition, has p 8.2 % below p at the next temperature (0.121 MeV) while eps rises by 2.0e-6
//    (0.03 %): a thermal index (dp/deps)_rho / rho of 158 on the first T interval, 5.0 on the next.
//    The star's crust (rho 0.95e-4 .. 1.46e-4, Ye ~ 0.1) interpolates it: there the first T interval
//    has (dp/deps)_rho / rho up to 87 (0.5 .. 0.8 from T_1 up), a pressure response to heating that
//    adds ~0.36 to cs2 where the table's cs2 is 7e-3; the slightest heating by truncation error there
//    becomes a pressure step. Replacing p at that node (and at two milder ones: (1.377e-4, 0.0411),
//    index 5.1 vs 0.8; (2.843e-4, 0.3826), 1.3 vs 0.22) by the continuation from T_1, T_2 at load time
//    (an experiment then; EOS::table_repair_thermal_index now replaces the flagged one, opt-in): 4.88e-4, 1.64e-4, 5.1e-4 (800 converges,
//    order 1.6; xCFC 5.65e-4, 1.70e-4, 6.1e-4, was 8.6e-4 at 800); dropping the T_min row: 4.41e-4,
//    1.66e-4, 4.13e-4. Consistent with the 0.5 MeV star converging. The table's data, not code:
//    nothing to fix in the evolution; with this node repaired (or the star at T >= T_1) the drift
//    converges to 800.
//  - the rest at 1600 is not the table: with the node repaired, 1600 shows isolated packets at r = 0
//    (t ~ 10, 30, 44; 3.2e-5, 5.1e-4, 1.3e-4), between them the drift converges roughly at first order
//    (t in [35, 42]: 1.6e-4, 8.5e-5, 3.0e-5; [50, 60]: 1.85e-4, 5.6e-5, 3.3e-5). The
//    BU0 polytrope (ideal gas, same grid to r = 16) does the same at t ~ 57: t <= 60 3.45e-4, 1.04e-4,
//    7.3e-4 (MC: 9.6e-4 at 800, 1.4e-4 at 1600): a grid-scale packet from the stellar surface focused
//    at r = 0, whose peak there need not converge (amplitude ~ first-order surface error times R / width,
//    width ~ dx). Unchanged by the outer boundary (r = 24 with the same dx: identical to 6 digits),
//    Atmosphere::rho_thr 1e-12, TOV::samples 40000, CFL 0.2. So max |rho_c/rho_c0 - 1| over t <= 60
//    cannot be asserted at 1600 for any star here; a volume norm would be the measure to converge.
//  - excluded: eps(T) not monotonic near T_min (monotone_cell is 1 in every (rho, Ye) cell of the
//    slice, rho 1e-10 .. 1.4e-3); the face temperature clamp at T_min (complete_face_thermo: 0 of
//    8.6e6 faces below T_min at 800); the recovery tolerance (Con2Prim::tolerance 1e-14: 8.08e-4,
//    4.585e-3, unchanged); PPM alone (MC: 1.03e-3, 3.35e-3 at 800, 1600; with the T_min row dropped
//    7.8e-4, 8.0e-4); the signal speed: cs2 = 1 at faces (HLL at light speed) 3.7e-4, 3.8e-4, 3.1e-3 (with
//    the row dropped too: 3.2e-4, 1.26e-4, 2.1e-4);
//  - from before: not the energy that rule 8 adds (keeping tau leaves 6.5e-4 at 800); the linear
//    continuation below T_min one interval 3.9e-4, ten 4.7e-4 at 800 (it keeps the node's stiffness).
// Bounds: measured orders less about 0.3; amplitudes +50 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "EOS/readers.hpp"
#include "TOV/table_slice.hpp"
#include "remnant/driver.hpp"
#include "remnant_test/shared_tables.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;

struct Drift {
  double rho_c = 0, rho_c_6 = 0, rho_c_25 = 0, rest_mass = 0, budget = 0;  // max |rho_c/rho_c0 - 1| (t <= 6, 25)
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
    if (r.time <= 25) d.rho_c_25 = std::max(d.rho_c_25, drift);
    d.budget = std::max(d.budget, std::abs(r.mass_budget / rows.front().mass_budget - 1));
  }
  d.rest_mass = rows.back().rest_mass / rows.front().rest_mass - 1;
  std::filesystem::remove_all(out);
  return d;
}

double order(double coarse, double fine) { return std::log2(coarse / fine); }

void expect_star_holds(const char* parfile, const char* name, double max_drift_200, double max_drift_400) {
  const Drift a = run(parfile, 200), b = run(parfile, 400), c = run(parfile, 800, 25);
  std::printf("SFHo static star, %s: max|rho_c/rho_c0 - 1| = %.3e %.3e at 200, 400 cells (t <= 150); "
              "t <= 6: %.3e %.3e %.3e (orders %.2f %.2f); t <= 25: %.3e %.3e %.3e (orders %.2f %.2f) at 200, 400, "
              "800; rest mass %.1e %.1e; budget %.1e %.1e\n",
              name, a.rho_c, b.rho_c, a.rho_c_6, b.rho_c_6, c.rho_c_6, order(a.rho_c_6, b.rho_c_6),
              order(b.rho_c_6, c.rho_c_6), a.rho_c_25, b.rho_c_25, c.rho_c_25, order(a.rho_c_25, b.rho_c_25),
              order(b.rho_c_25, c.rho_c_25), a.rest_mass, b.rest_mass, a.budget, b.budget);
  EXPECT_GT(order(a.rho_c_6, b.rho_c_6), 1.45) << name;
  EXPECT_GT(order(b.rho_c_6, c.rho_c_6), 1.45) << name << ": the initial data must converge with the grid";
  EXPECT_GT(order(a.rho_c_25, b.rho_c_25), 1.4) << name;
  EXPECT_GT(order(b.rho_c_25, c.rho_c_25), 1.45) << name << ": no pulses from the table's kinks";
  EXPECT_LT(c.rho_c_25, 8.5e-5) << name;
  EXPECT_LT(a.rho_c, max_drift_200) << name;
  EXPECT_LT(b.rho_c, max_drift_400) << name;
  for (const Drift& d : {a, b}) {
    EXPECT_LT(std::abs(d.rest_mass), 2e-8) << name;
    EXPECT_LT(d.budget, 1e-12) << name;
  }
}

}  // namespace

TEST(TabulatedStaticStar, SFHoCowling) {
  REQUIRE_TABLE(remnant::test::shared_eos("SFHo_reduced_39r_39t_20y.h5"));
  expect_star_holds("bu0_cow.yaml", "Cowling", 2.2e-3, 1e-3);
}

TEST(TabulatedStaticStar, SFHoWithXCFC) {
  REQUIRE_TABLE(remnant::test::shared_eos("SFHo_reduced_39r_39t_20y.h5"));
  expect_star_holds("bu0_dyn.yaml", "xCFC every step", 2.2e-3, 1e-3);
}

// The cold slice is in hydrostatic balance with the table the evolution interpolates: dp/dH = e + p on
// both sides of every kink of the interpolated table inside the star (its density nodes and the
// densities where beta-equilibrium Ye crosses a Ye node). A monotone spline of ln rho(H) over the
// samples between density nodes was off there by up to 0.3 % (nodes) and 16 % (Ye crossings inside its
// pieces) within a sample interval: a pressure-gradient error that the evolution felt as a pulse from
// every node (measured now: 5.8e-8 worst, round-off of the differences included; bound 1e-6).
TEST(TabulatedStaticStar, ColdSliceIsBalancedAtTheTableKinks) {
  const std::string path = remnant::test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
  REQUIRE_TABLE(path);
  const remnant::eos::Tabulated<> table(remnant::eos::load_table(path));
  const auto slice = remnant::tov::cold_beta_slice(table);
  const double dx = table.table().lrho.dx;
  int kinks = 0, crossings = 0;
  double worst = 0;
  for (double x : remnant::tov::slice_kinks(table)) {
    if (x < std::log(1e-10) || x > std::log(1.4e-3)) continue;  // the star, atmosphere excluded
    ++kinks;
    const double node = (x - table.table().lrho.x0) / dx;
    if (std::abs(node - std::round(node)) > 1e-6) ++crossings;
    for (double side : {-1.0, 1.0})
      for (double offset : {1e-4, 1e-3, 1e-2}) {
        const double xc = x + side * offset * dx, d = 1e-3 * offset * dx;
        const auto lo = remnant::tov::cold_beta_state(table, std::exp(xc - d));
        const auto hi = remnant::tov::cold_beta_state(table, std::exp(xc + d));
        const auto c = remnant::tov::cold_beta_state(table, std::exp(xc));
        const double dp_dH = (hi.press - lo.press) / (slice->log_enthalpy(hi.rho) - slice->log_enthalpy(lo.rho));
        worst = std::max(worst, std::abs(dp_dH / (c.rho * (1 + c.eps) + c.press) - 1));
      }
  }
  std::printf("cold SFHo slice: %d kinks in the star (%d Ye-node crossings), worst |dp/dH / (e + p) - 1| = %.2e\n",
              kinks, crossings, worst);
  EXPECT_GT(crossings, 5);
  EXPECT_LT(worst, 1e-6);
}
