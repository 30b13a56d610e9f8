// The hand-off report's metric comparison against a known metric, and data off the 3D origin.
// The BU0 TOV star (K = 100, Gamma = 2, rho_c = 1.28e-3) as 3D Carpet data whose ADMBase metric is
// the TOV's isotropic one made anisotropic at fixed determinant (gxx = psi^4 (1 + eps), gyy =
// psi^4 / (1 + eps), gzz = psi^4: gamma^(1/3) and sqrt(gamma) stay psi^4, psi^6) and whose lapse is
// the TOV's times (1 + delta): the report's psi^4 vs gamma^(1/3) must stay at the discretisation
// error (a comparison with gxx alone shows eps), its alpha vs the 3D lapse must show delta, and the
// 3D metric it interpolated to the cells must be the analytic one. Real Einstein Toolkit runs
// rarely have the remnant at the 3D origin (the ReadInterpolate thorn's TOV test data: the star
// at (-3.14, 42, 6)); HandOff::centre places the data's point at the grid's origin.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <span>
#include <string>
#include <vector>

#include "HandOff/handoff_state.hpp"
#include "TOV/tov_solver.hpp"
#include "remnant/driver.hpp"
#include "handoff_profiles.hpp"
#include "synthetic_carpet.hpp"
#include "tov_carpet_data.hpp"

namespace {

using namespace remnant;

constexpr double kEps = 0.05;    // gxx, gyy anisotropy at fixed determinant
constexpr double kDelta = 0.02;  // the data's lapse / the TOV's - 1

struct MetricTov : handoff_test::TovCarpetData {
  // centre: the star's centre in the data's coordinates; whole: data of the whole star (no mirrors),
  // else an octant (centre 0).
  MetricTov(const std::string& name, std::array<double, 3> centre, double eps, double delta, bool whole)
      : TovCarpetData("handoff_metric_" + name) {
    handoff::synthetic::SyntheticCarpet spec;
    spec.variables = {"HYDROBASE::rho", "HYDROBASE::press", "HYDROBASE::eps", "ADMBASE::alp", "ADMBASE::gxx",
                      "ADMBASE::gxy", "ADMBASE::gxz", "ADMBASE::gyy", "ADMBASE::gyz", "ADMBASE::gzz"};
    const auto& c = centre;
    if (!whole) {  // an octant, as the other HandOff tests
      spec.levels = {{1.0, {0.5, 0.5, 0.5}, {16, 16, 16}, 0}, {0.5, {0, 0, 0}, {21, 21, 21}, 1}};
    } else {
      spec.reflection = {false, false, false};
      spec.levels = {{1.0, {c[0] - 15.5, c[1] - 15.5, c[2] - 15.5}, {32, 32, 32}, 0},
                     {0.5, {c[0] - 10, c[1] - 10, c[2] - 10}, {41, 41, 41}, 1}};
    }
    write(spec, [this, c, eps, delta](const std::string& v, int, double x, double y, double z) {
      const double dx = x - c[0], dy = y - c[1], dz = z - c[2];
      const tov::TovPoint p = star.at(std::sqrt(dx * dx + dy * dy + dz * dz));
      const double psi4 = std::pow(p.psi, 4);
      if (v == "HYDROBASE::rho") return p.rho;
      if (v == "HYDROBASE::press") return p.press;
      if (v == "HYDROBASE::eps") return p.eps;
      if (v == "ADMBASE::alp") return p.alpha * (1 + delta);
      if (v == "ADMBASE::gxx") return psi4 * (1 + eps);
      if (v == "ADMBASE::gyy") return psi4 / (1 + eps);
      if (v == "ADMBASE::gzz") return psi4;
      return 0.0;
    });
  }
};

struct Result {
  handoff::HandOffReport report;
  std::vector<std::array<double, 11>> profiles;  // handoff_profiles.tsv
};

Result hand_off(const MetricTov& data, const std::vector<std::string>& more) {
  const auto out = data.dir / "out";
  std::vector<std::string> settings = {"MoL::final_time=0", "HandOff::buffer_zones=2", "Flesh::out_dir=" + out.string()};
  settings.insert(settings.end(), more.begin(), more.end());
  Simulation sim(handoff_test::compiled_catalog(), handoff_test::handoff_options(data, settings), MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  Result r;
  r.report = sim.context().service<handoff::HandOffState>("HandOff::state").report;
  r.profiles = handoff_test::read_handoff_profiles(out / "handoff_profiles.tsv");
  return r;
}

TEST(HandOffMetricReport, AgainstAnalyticMetric) {
  const MetricTov data("analytic", {0, 0, 0}, kEps, kDelta, false);
  const Result r = hand_off(data, {});
  const auto& h = r.report;
  // The 3D metric at the cells (profiles: gamma13_3d, alpha_3d) against the analytic values there.
  double dgamma = 0, dalpha = 0;
  int inside = 0;
  for (const auto& v : r.profiles) {
    const tov::TovPoint p = data.star.at(std::sqrt(v[2] * v[2] + v[3] * v[3] + v[4] * v[4]));
    if (p.rho <= 0) continue;
    ++inside;
    dgamma = std::max(dgamma, std::abs(v[7] / std::pow(p.psi, 4) - 1));
    dalpha = std::max(dalpha, std::abs(v[9] / (p.alpha * (1 + kDelta)) - 1));
  }
  const double expected_alpha = kDelta / (1 + kDelta);  // |alpha_TOV / (alpha_TOV (1 + delta)) - 1|
  std::printf("metric report (gxx, gyy anisotropic by %.2f at fixed det, alp x %.2f): psi4 vs gamma^(1/3) max %.2e mean %.2e; "
              "alpha vs 3D max %.4e mean %.4e (expected %.4e); 3D metric at %d cells vs analytic: gamma^(1/3) %.1e, alpha %.1e; "
              "centre gamma^(1/3) %.6f psi^4 %.6f alpha_3D %.6f alpha %.6f\n",
              kEps, 1 + kDelta, h.psi4_max_rel, h.psi4_mean_rel, h.alpha_max_rel, h.alpha_mean_rel, expected_alpha, inside,
              dgamma, dalpha, h.gamma13_c, h.psi4_c, h.alpha3d_c, h.alpha_c);
  ASSERT_TRUE(h.has_metric);
  ASSERT_TRUE(h.has_lapse);
  ASSERT_GT(inside, 40);
  EXPECT_LT(dgamma, 5e-4);  // gamma^(1/3) = the determinant's cube root, not gxx (5e-2 off)
  EXPECT_LT(dalpha, 5e-4);
  EXPECT_LT(h.psi4_max_rel, 1e-3);
  EXPECT_LT(h.psi4_mean_rel, 5e-4);
  EXPECT_NEAR(h.alpha_mean_rel, expected_alpha, 1e-3);
  EXPECT_NEAR(h.alpha_max_rel, expected_alpha, 2e-3);
  EXPECT_NEAR(h.alpha_c / h.alpha3d_c, 1 / (1 + kDelta), 1e-3);
  EXPECT_NEAR(h.psi4_c / h.gamma13_c, 1.0, 1e-3);
}

// The star centred at c in the data's coordinates, whole (no mirrors): without HandOff::centre a
// grid around the origin holds none of it (an error); with it, the hand-off is that of the same
// data centred at the origin.
TEST(HandOffMetricReport, OffCentreDataWithCentre) {
  const MetricTov shifted("shifted", {-3.5, 42.0, 6.0}, 0, 0, true);
  const MetricTov centred("centred", {0, 0, 0}, 0, 0, true);
  const std::string e = handoff_test::message_of([&] { hand_off(shifted, {}); });
  EXPECT_NE(e.find("the grid cuts the star"), std::string::npos) << e;
  const Result a = hand_off(shifted, {"HandOff::centre=[-3.5,42,6]"});
  const Result b = hand_off(centred, {});
  const auto &ha = a.report, &hb = b.report;
  std::printf("star at (-3.5, 42, 6) with HandOff::centre vs at the origin: M0 on the grid %.12f vs %.12f, rho_c %.9e vs %.9e, "
              "psi^4 vs gamma^(1/3) %.3e vs %.3e, alpha %.3e vs %.3e, outside %.1e\n",
              ha.source_grid.rest_mass, hb.source_grid.rest_mass, ha.rho_c, hb.rho_c, ha.psi4_max_rel, hb.psi4_max_rel,
              ha.alpha_max_rel, hb.alpha_max_rel, ha.outside_fraction);
  EXPECT_LT(ha.outside_fraction, 1e-12);
  EXPECT_NEAR(ha.source_grid.rest_mass / hb.source_grid.rest_mass, 1.0, 1e-12);
  EXPECT_NEAR(ha.imported.rest_mass / ha.source_grid.rest_mass, 1.0, 1e-13);
  EXPECT_NEAR(ha.rho_c / hb.rho_c, 1.0, 1e-9);
  EXPECT_NEAR(ha.psi4_max_rel, hb.psi4_max_rel, 1e-9);
  EXPECT_NEAR(ha.alpha_max_rel, hb.alpha_max_rel, 1e-9);
}

}  // namespace
