// The tabulated EOS through the whole chain for 1 ms (issue 20, item 4): the static SFHo star of
// test_tabulated_star.cpp (cold beta-equilibrium slice of the reduced SFHo table, rho_c = 1.4e-3,
// 1D spherical to r = 16) evolved with the table to t = 203 (1.0 ms; ~ 20 sound crossings of the
// star, R = 6.94 isotropic) in Cowling and with xCFC solved every step, with
// EOS::table_repair_thermal_index = true. The drift of the density profile must converge with the
// grid and must not grow over the millisecond.
//
// Norm (drift_probe.hpp): the rest-mass-weighted mean of |rho/rho0 - 1| over the grid,
// sum psi0^6 dV |rho - rho0| / sum psi0^6 dV rho0. Each shell counts by its mass; mass pushed into
// the atmosphere counts fully. Not rho_c: grid-scale packets from the surface focus at r = 0 (BU0
// ideal gas as well) and their peak there need not converge (test_tabulated_star.cpp: rho_c at 1600
// cells reaches 4.6e-3 by t = 60 while the mass norm stays at 5e-5); weighted by mass such a packet
// counts with its volume, ~ dx^3.
//
// max_t<=T mass norm, Cowling, at 200, 400, 800, 1600 cells (survey: TabulatedDrift.DISABLED_Survey):
//   repaired table, T = 6:    3.89e-4, 6.43e-5, 2.49e-5, 9.26e-6
//                   T = 25:   7.57e-4, 1.11e-4, 3.46e-5, 1.12e-5
//                   T = 203:  1.05e-3, 1.33e-4, 3.57e-5, 1.18e-5 (orders 2.98, 1.90, 1.60)
//   table as is,    T = 6:    4.04e-4, 8.86e-5, 5.65e-5, 3.94e-5
//                   T = 203:  1.07e-3, 1.81e-4, 7.42e-5, 6.84e-5 (orders 2.56, 1.29, 0.12): the node
//     (1.377e-4, T_min, Ye 0.0721) whose thermal index is 158 (EOS check `thermal_index`) sits at the
//     crust-core transition, r ~ 6; by t = 1 the cells there are off by 1e-2 at 1600 cells, and
//     r in [5, 6.5] holds 3.2e-5 of the 3.3e-5 that the norm then has (repaired: 7.9e-6).
// xCFC every step (the same runs with bu0_dyn.yaml):
//   repaired table, T = 25:   7.56e-4, 1.12e-4, 3.52e-5, 1.13e-5
//                   T = 203:  1.05e-3, 1.45e-4, 4.26e-5, 1.55e-5 (orders 2.86, 1.77, 1.46)
//   table as is,    T = 203:  1.06e-3, 2.11e-4, 7.29e-5, 6.93e-5 (orders 2.32, 1.53, 0.07).
// The maximum over the run is reached in the last window (150, 203]; it exceeds that of (6, 25] by
// 3 % (Cowling, 800 and 1600 cells) and 21 %, 37 % (xCFC): no secular growth to speak of.
// Asserted at 400, 800, 1600 cells (200 is not yet in the asymptotic range): orders of the maximum
// and of the last window above the measured ones less about 0.3 (1.45; 1.3 Cowling, 1.2 xCFC), the
// maximum at 1600 below 1.5x the measured one, the last window below 1.5x the (6, 25] one. The table
// as is fails the 800 -> 1600 orders (0.12, 0.07) and the amplitudes (6.8e-5, 6.9e-5).
// Cost: three runs to t = 203 per test, about 31 s on one core (1600 cells: 3/4 of it).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "drift_probe.hpp"
#include "remnant_test/shared_tables.hpp"

namespace {

using namespace remnant::test;

constexpr double kOneMs = 203.0;  // 1 ms in code units (4.9255e-6 s)

std::vector<std::string> star_overrides(int n, double final_time) {
  return {"EOS::type=tabulated",
          "EOS::table_file=" + shared_eos("SFHo_reduced_39r_39t_20y.h5"),
          "TOV::eos_slice=tabulated_beta",
          "TOV::rho_central=1.4e-3",
          "Grid::ncells=[" + std::to_string(n) + ",1,1]",
          "Grid::block_size=[" + std::to_string(n / 8) + ",1,1]",
          "Grid::xmax=[16,3.141592653589793,6.283185307179586]",
          "MoL::final_time=" + std::to_string(final_time)};
}

double window_max(const std::vector<DriftSample>& s, double t0, double t1) {
  double m = 0;
  for (const DriftSample& d : s)
    if (d.time > t0 && d.time <= t1 + 1e-9) m = std::max(m, d.mass);
  return m;
}

void expect_drift_converges(const char* parfile, const char* name, double min_order_fine, double max_1600) {
  double total[3], early[3], late[3];
  const int cells[3] = {400, 800, 1600};
  for (int i = 0; i < 3; ++i) {
    auto o = star_overrides(cells[i], kOneMs);
    o.push_back("EOS::table_repair_thermal_index=true");
    const auto s = drift_series(parfile, o);
    ASSERT_NEAR(s.back().time, kOneMs, 1e-6) << name << ": the run stopped early";
    total[i] = max_until(s, kOneMs, &DriftSample::mass);
    early[i] = window_max(s, 6, 25);
    late[i] = window_max(s, 150, kOneMs);
  }
  const double o1 = std::log2(total[0] / total[1]), o2 = std::log2(total[1] / total[2]);
  std::printf("SFHo static star, %s, repaired table: max_t<=203 mass-weighted |rho/rho0 - 1| = %.3e %.3e %.3e at "
              "400, 800, 1600 cells (orders %.2f %.2f); (6, 25]: %.3e %.3e %.3e; (150, 203]: %.3e %.3e %.3e\n",
              name, total[0], total[1], total[2], o1, o2, early[0], early[1], early[2], late[0], late[1], late[2]);
  EXPECT_GT(o1, 1.45) << name;
  EXPECT_GT(o2, min_order_fine) << name << ": the drift over 1 ms must converge with the grid";
  EXPECT_GT(std::log2(late[1] / late[2]), min_order_fine) << name << ": and still at the end of the millisecond";
  EXPECT_LT(total[2], max_1600) << name;
  for (int i = 0; i < 3; ++i) EXPECT_LT(late[i], 1.5 * early[i]) << name << ": the drift grows, " << cells[i] << " cells";
}

std::string env(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v ? v : fallback;
}

}  // namespace

TEST(TabulatedStarDrift, SFHoCowlingConvergesOverOneMillisecond) {
  REQUIRE_TABLE(shared_eos("SFHo_reduced_39r_39t_20y.h5"));
  expect_drift_converges("bu0_cow.yaml", "Cowling", 1.3, 1.8e-5);
}

TEST(TabulatedStarDrift, SFHoWithXCFCConvergesOverOneMillisecond) {
  REQUIRE_TABLE(shared_eos("SFHo_reduced_39r_39t_20y.h5"));
  expect_drift_converges("bu0_dyn.yaml", "xCFC every step", 1.2, 2.3e-5);
}

// The measurements above (run with --gtest_also_run_disabled_tests). Environment: DRIFT_PARFILE
// (bu0_cow.yaml), DRIFT_CELLS ("200 400 800"), DRIFT_T (203), DRIFT_OVERRIDES (space-separated, e.g.
// EOS::table_repair_thermal_index=true), DRIFT_TSV (a file for the series "n t mass centre" and,
// with DRIFT_PROFILE_T, the profile "P n r rho0 rho" at that time).
TEST(TabulatedStarDrift, DISABLED_Survey) {
  const std::string parfile = env("DRIFT_PARFILE", "bu0_cow.yaml");
  const double T = std::atof(env("DRIFT_T", "203").c_str());
  std::istringstream cells(env("DRIFT_CELLS", "200 400 800"));
  const std::string tsv = env("DRIFT_TSV", "");
  FILE* f = tsv.empty() ? nullptr : std::fopen(tsv.c_str(), "w");
  const double ends[] = {6, 25, 50, 75, 100, 150, 203, 300, 400};
  for (int n; cells >> n;) {
    auto o = star_overrides(n, T);
    std::istringstream extra(env("DRIFT_OVERRIDES", ""));
    for (std::string s; extra >> s;) o.push_back(s);
    drift_probe().snapshot_time = std::atof(env("DRIFT_PROFILE_T", "-1").c_str());
    const auto s = drift_series(parfile, o);
    if (f)
      for (const auto& q : drift_probe().snapshot) std::fprintf(f, "P %d %.6f %.8e %.8e\n", n, q[0], q[1], q[2]);
    std::printf("%s n=%d t_end=%.1f\n  T     max mass     max centre   | window max mass\n", parfile.c_str(), n,
                s.back().time);
    double prev = 0;
    for (double e : ends) {
      if (e > T + 1e-9) break;
      std::printf("  %-5g %.4e   %.4e   | (%g, %g] %.4e\n", e, max_until(s, e, &DriftSample::mass),
                  max_until(s, e, &DriftSample::centre), prev, e, window_max(s, prev, e));
      prev = e;
    }
    if (f)
      for (const auto& d : s) std::fprintf(f, "%d %.6f %.6e %.6e\n", n, d.time, d.mass, d.centre);
    std::fflush(stdout);
  }
  if (f) std::fclose(f);
}
