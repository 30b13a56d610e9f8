// Load-time table checks: each problem is a TableError naming file and dataset, or a counted
// warning in the report. Never a crash or a silent NaN.
#include <sstream>

#include "EOS/errors.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "eos_test_util.hpp"

using namespace remnant::eos;
using eos_test::Synthetic;

namespace {

// Expects load_table(path) to throw a TableError whose message names `path` and `dataset`.
void expect_table_error(const std::string& path, const std::string& dataset, const std::string& words) {
  try {
    load_table(path);
    ADD_FAILURE() << "no error for " << path << " (" << dataset << ")";
  } catch (const TableError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find(dataset), std::string::npos) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
    EXPECT_EQ(e.dataset(), dataset);
  }
}

const double kShift = 0.02 * remnant::units::c2_cgs;

}  // namespace

TEST(EOSChecks, MissingDataset) {
  const std::string path = eos_test::temp_path("missing.h5");
  eos_test::write_stellarcollapse(path, Synthetic().raw(), kShift, "logpress");
  expect_table_error(path, "logpress", "missing");
}

TEST(EOSChecks, MisShapedDataset) {
  const std::string path = eos_test::temp_path("misshaped.h5");
  eos_test::write_stellarcollapse(path, Synthetic().raw(), kShift, "", "cs2");
  expect_table_error(path, "cs2", "shape");
}

TEST(EOSChecks, NonUniformAxis) {
  auto raw = Synthetic().raw();
  raw.rho[5] *= 1.01;
  const std::string path = eos_test::temp_path("nonuniform.h5");
  eos_test::write_stellarcollapse(path, raw, kShift);
  expect_table_error(path, "logrho", "not uniform");
}

TEST(EOSChecks, NaNIsAnErrorNamingTheDataset) {
  auto raw = Synthetic().raw();
  raw.eps.v[17] = std::nan("");
  const std::string path = eos_test::temp_path("nan.h5");
  eos_test::write_stellarcollapse(path, raw, kShift);
  expect_table_error(path, "logenergy", "NaN/Inf");
  raw = Synthetic().raw();
  raw.mu_n.v[3] = INFINITY;
  eos_test::write_stellarcollapse(path, raw, kShift);
  expect_table_error(path, "mu_n", "NaN/Inf");
}

TEST(EOSChecks, NotAnHdf5FileAndMissingFile) {
  EXPECT_THROW(load_table(eos_test::temp_path("does_not_exist.h5")), TableError);
  const std::string dir = eos_test::temp_path("compose_empty");
  std::filesystem::create_directories(dir);
  EXPECT_THROW(load_table(dir), TableError);
}

TEST(EOSChecks, Cs2OutsideUnitIntervalIsCountedAndClamped) {
  auto raw = Synthetic().raw();
  raw.cs2.v[0] = -0.01;
  raw.cs2.v[1] = 1.3;
  raw.cs2.v[2] = 1.1;
  const std::string path = eos_test::temp_path("cs2.h5");
  eos_test::write_stellarcollapse(path, raw, kShift);
  auto t = load_table(path);
  const CheckIssue* w = t->report.find("cs2");
  ASSERT_NE(w, nullptr) << t->report.str();
  EXPECT_EQ(w->count, 3u);
  EXPECT_EQ(w->file, path);
  Tabulated<> eos(t);
  EXPECT_GE(eos.cs2(raw.rho[0], raw.T[0], raw.ye[0]), 0.0);
  EXPECT_LE(eos.cs2(raw.rho[1], raw.T[0], raw.ye[0]), 1.0);
  // cs2 > 1 marks the (rho, Ye) cells around those points as acausal (con2prim scans roots there);
  // cs2 < 0 alone does not.
  EXPECT_TRUE(eos.acausal(std::sqrt(raw.rho[1] * raw.rho[2]), raw.ye[0]));
  EXPECT_TRUE(eos.acausal(std::sqrt(raw.rho[0] * raw.rho[1]), raw.ye[0]));
  EXPECT_FALSE(eos.acausal(std::sqrt(raw.rho[5] * raw.rho[6]), raw.ye[0]));
  EXPECT_FALSE(eos.acausal(raw.rho[1], raw.ye[3]));
}

TEST(EOSChecks, NonMonotonicEpsIsCountedAndInversionFollowsTheGuess) {
  Synthetic s;
  auto raw = s.raw();
  // Make eps dip between T nodes 3 and 4 in one column (irho = 2, iYe = 1).
  const std::size_t nr = raw.rho.size(), nt = raw.T.size();
  auto idx = [&](int ir, int it, int iy) { return (std::size_t(iy) * nt + it) * nr + ir; };
  raw.eps.v[idx(2, 4, 1)] = raw.eps.v[idx(2, 2, 1)];
  auto t = build_table(raw);
  const CheckIssue* w = t->report.find("eps");
  ASSERT_NE(w, nullptr) << t->report.str();
  EXPECT_EQ(w->count, 1u);
  // At that column, eps(T node 3) is reached at two temperatures: the guess picks the root.
  Tabulated<> eos(t);
  const double rho = raw.rho[2], ye = raw.ye[1];
  const double e3 = raw.eps.v[idx(2, 3, 1)];
  const double e_target = 0.5 * (e3 + raw.eps.v[idx(2, 2, 1)]);  // reached below node 3 and again after 4
  const Inversion low = eos.temperature(rho, e_target, ye, raw.T[2]);
  const Inversion high = eos.temperature(rho, e_target, ye, raw.T[5]);
  EXPECT_LT(low.T, raw.T[3]);
  EXPECT_GT(high.T, raw.T[4]);
  EXPECT_NEAR(eos.eps(rho, low.T, ye) / e_target, 1.0, 1e-12);
  EXPECT_NEAR(eos.eps(rho, high.T, ye) / e_target, 1.0, 1e-12);
}

TEST(EOSChecks, NegativePressureIsShiftedAndReported) {
  auto raw = Synthetic().raw();
  raw.press.v[10] = -1e-30;
  auto t = build_table(raw);
  EXPECT_GT(t->p_shift, 0.0);
  ASSERT_NE(t->report.find("press"), nullptr);
  Tabulated<> eos(t);
  const std::size_t nr = raw.rho.size();
  EXPECT_NEAR(eos.press(raw.rho[10 % nr], raw.T[0], raw.ye[0]), -1e-30, 1e-40);
}

// --- issue 16, item 10: tables that used to load without complaint --------------------------------

TEST(EOSChecks, YeAxisOutsideTheUnitIntervalIsAnError) {
  Synthetic s;
  s.y0 = -0.2, s.y1 = 1.4;
  const std::string path = eos_test::temp_path("ye_range.h5");
  eos_test::write_stellarcollapse(path, s.raw(), kShift);
  expect_table_error(path, "ye", "must lie in [0, 1]");
}

TEST(EOSChecks, LogPressStoredAsIntegersIsAnError) {
  const std::string path = eos_test::temp_path("int_logpress.h5");
  eos_test::write_stellarcollapse(path, Synthetic().raw(), kShift, "", "", "logpress");
  expect_table_error(path, "logpress", "stored as integers");
}

TEST(EOSChecks, IntegerScalarsAndAxesOfCountsStayAllowed) {
  // energy_shift as int32 (the shared Hempel table stores it so) still loads.
  const std::string path = eos_test::temp_path("int_shift.h5");
  eos_test::write_stellarcollapse(path, Synthetic().raw(), 2e19, "", "", "energy_shift");
  EXPECT_NO_THROW(load_table(path));
}

TEST(EOSChecks, IncompleteCompositionIsReportedAndNotUsed) {
  const std::string path = eos_test::temp_path("no_xa.h5");
  eos_test::write_stellarcollapse(path, Synthetic().raw(), kShift, "Xa", "", "", true);
  auto t = load_table(path);
  EXPECT_FALSE(t->has_compo);
  const CheckIssue* w = t->report.find("composition");
  ASSERT_NE(w, nullptr) << t->report.str();
  EXPECT_NE(w->message.find("Xa"), std::string::npos) << w->message;
  // With every field present, composition is on.
  eos_test::write_stellarcollapse(path, Synthetic().raw(), kShift, "", "", "", true);
  EXPECT_TRUE(load_table(path)->has_compo);
}

TEST(EOSChecks, OnePressure27OrdersOffIsAnError) {
  for (double factor : {1e27, 1e-27}) {
    auto raw = Synthetic().raw();
    raw.press.v[3 * raw.rho.size() + 5] *= factor;  // irho = 5 at iT = 3, iYe = 0
    const std::string path = eos_test::temp_path("spike.h5");
    eos_test::write_stellarcollapse(path, raw, kShift);
    expect_table_error(path, "logpress", "corrupted value");
  }
}

TEST(EOSChecks, SmallPressureDipIsCountedNotFatal) {
  auto raw = Synthetic().raw();
  raw.press.v[6] = 0.9 * raw.press.v[5];  // a dip of 10 %: as in a blend region
  auto t = build_table(raw);
  const CheckIssue* w = t->report.find("press");
  ASSERT_NE(w, nullptr) << t->report.str();
  EXPECT_EQ(w->count, 1u);
}

TEST(EOSChecks, TooManyInconsistentPointsStopTheLoad) {
  auto raw = Synthetic().raw();
  for (std::size_t i = 0; i < raw.cs2.v.size(); i += 4) raw.cs2.v[i] = 1.5;  // 25 % acausal
  try {
    build_table(raw);
    ADD_FAILURE() << "no error";
  } catch (const TableError& e) {
    EXPECT_NE(std::string(e.what()).find("fail at"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("25 %"), std::string::npos) << e.what();
  }
  BuildOptions lax;
  lax.max_inconsistent_fraction = 0.3;
  EXPECT_NO_THROW(build_table(raw, lax));
}

TEST(EOSChecks, SharedTablesPassTheConsistencyChecks) {
  for (const char* name : {"SFHo_reduced_39r_39t_20y.h5", "Hempel_SFHoEOS_rho222_temp180_ye60_version_1.1_20120817_simple.h5",
                           "SFHo_psolver_compose.h5", "SFHo_reduced_39r_39t_20y_compose.h5"}) {
    const std::string path = eos_test::shared_eos(name);
    if (!std::filesystem::exists(path)) continue;
    ReadOptions o;  // the SFHo StellarCollapse file holds relativistic cs2 without saying so
    if (std::string(name) == "SFHo_reduced_39r_39t_20y.h5") o.sc_cs2 = Cs2Convention::relativistic;
    std::shared_ptr<const TableData> t;
    EXPECT_NO_THROW(t = load_table(path, o)) << name;
    if (t) std::printf("%s:\n%s", name, t->report.str().c_str());
  }
}

// --- thermal index (dp/deps)_rho / rho along T: check_thermal_index.cpp -------------------------

namespace {
// A smooth table whose thermal index is large (28 .. 80) but constant along T: only a jump between
// neighbouring T intervals may warn, not the size alone.
Synthetic hot_index_table() {
  Synthetic s;
  s.logp = {-3.0 + std::log(20.0), 1.0, 0.8, 0.0};
  s.logeps = {-3.0, 0.05, 0.8, 0.0};
  return s;
}
}  // namespace

TEST(EOSChecks, SmoothTableHasNoThermalIndexWarning) {
  auto t = build_table(hot_index_table().raw());
  EXPECT_EQ(t->report.find("thermal_index"), nullptr) << t->report.str();
}

TEST(EOSChecks, ThermalIndexJumpIsAWarningNamingTheNode) {
  auto raw = hot_index_table().raw();
  const std::size_t nr = raw.rho.size(), nt = raw.T.size();
  auto idx = [&](int ir, int it, int iy) { return (std::size_t(iy) * nt + it) * nr + ir; };
  // As in the reduced SFHo table: at T_min eps sits just below the next temperature's while p does
  // not, so the first interval's index is 100x the next one's.
  const int ir = 7, iy = 3;
  double& e0 = raw.eps.v[idx(ir, 0, iy)];
  const double e1 = raw.eps.v[idx(ir, 1, iy)];
  e0 = e1 - 0.01 * (e1 - e0);
  std::shared_ptr<const TableData> t;
  ASSERT_NO_THROW(t = build_table(raw));  // a warning, not an error
  const CheckIssue* w = t->report.find("thermal_index");
  ASSERT_NE(w, nullptr) << t->report.str();
  EXPECT_EQ(w->count, 1u);
  const std::string& m = w->message;
  EXPECT_NE(m.find("(irho, iT, iYe) = (7, 0, 3)"), std::string::npos) << m;
  std::ostringstream rho_cgs;
  rho_cgs.precision(4);
  rho_cgs << raw.rho[ir] * remnant::units::density_cgs << " g/cm^3";
  EXPECT_NE(m.find(rho_cgs.str()), std::string::npos) << m;
  EXPECT_NE(m.find("pressure step"), std::string::npos) << m;
  // Above a stricter threshold the same node is not flagged.
  BuildOptions lax;
  lax.thermal_index_jump = 200;
  EXPECT_EQ(build_table(raw, lax)->report.find("thermal_index"), nullptr);
}

TEST(EOSChecks, SharedReducedSFHoReportsItsThermalIndexNode) {
  const std::string path = eos_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
  REQUIRE_TABLE(path);
  ReadOptions o;
  o.sc_cs2 = Cs2Convention::relativistic;
  auto t = load_table(path, o);
  const CheckIssue* w = t->report.find("thermal_index");
  ASSERT_NE(w, nullptr) << t->report.str();
  EXPECT_EQ(w->count, 1u) << w->message;
  // The node found by the tabulated-star study (TOV/test/test_tabulated_star.cpp): index 158 vs 5.0.
  EXPECT_NE(w->message.find("(irho, iT, iYe) = (34, 0, 2)"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("0.0001377 code"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("index 158.3 against 4.969"), std::string::npos) << w->message;
}

// EOS::table_repair_thermal_index: the outlying node's pressure is replaced by log p linear in log T
// from its column (exact for this table, which is log-linear in log T), the check then passes, and
// the repair is a warning naming the node. Without the option the same table only warns.
TEST(EOSChecks, ThermalIndexRepairReplacesTheOutlyingPressure) {
  // Like cold degenerate matter: p and eps change little with T, so a 30 % error in p at T_min makes
  // the first interval's index 15x the next one's.
  Synthetic cold;
  cold.logp = {-3.0 + std::log(20.0), 1.0, 0.02, 0.0};
  cold.logeps = {-3.0, 0.05, 0.02, 0.0};
  auto raw = cold.raw();
  const std::size_t nr = raw.rho.size(), nt = raw.T.size();
  auto idx = [&](int ir, int it, int iy) { return (std::size_t(iy) * nt + it) * nr + ir; };
  const int ir = 7, iy = 3;
  const double p_true = raw.press.v[idx(ir, 0, iy)];
  raw.press.v[idx(ir, 0, iy)] = 0.7 * p_true;  // p at T_min below the column's trend
  const auto plain = build_table(raw);
  ASSERT_NE(plain->report.find("thermal_index"), nullptr) << plain->report.str();
  EXPECT_EQ(plain->report.find("thermal_index_repair"), nullptr);
  BuildOptions repair;
  repair.repair_thermal_index = true;
  const auto t = build_table(raw, repair);
  EXPECT_EQ(t->report.find("thermal_index"), nullptr) << t->report.str();
  const CheckIssue* w = t->report.find("thermal_index_repair");
  ASSERT_NE(w, nullptr) << t->report.str();
  EXPECT_EQ(w->count, 1u);
  EXPECT_NE(w->message.find("(irho, iT, iYe) = (7, 0, 3)"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("(code, 42.86 %)"), std::string::npos) << w->message;
  EXPECT_NEAR(std::exp(t->at(ir, 0, iy, kLogP)) - t->p_shift, p_true, 1e-12 * p_true);
  // Every other node is untouched.
  const auto ref = build_table(cold.raw(), repair);
  EXPECT_EQ(ref->report.find("thermal_index_repair"), nullptr);
  for (int k = 0; k < int(raw.size()); ++k)
    if (std::size_t(k) != idx(ir, 0, iy))
      ASSERT_EQ(t->thermo[k * kThermoStride + kLogP], ref->thermo[k * kThermoStride + kLogP]) << k;
}

// An outlier in eps (p follows its column) has no single-node pressure fix: nothing is replaced and
// the check still warns.
TEST(EOSChecks, ThermalIndexRepairLeavesAnEpsOutlierToTheWarning) {
  auto raw = hot_index_table().raw();
  const std::size_t nr = raw.rho.size(), nt = raw.T.size();
  auto idx = [&](int ir, int it, int iy) { return (std::size_t(iy) * nt + it) * nr + ir; };
  double& e0 = raw.eps.v[idx(7, 0, 3)];
  const double e1 = raw.eps.v[idx(7, 1, 3)];
  e0 = e1 - 0.01 * (e1 - e0);
  BuildOptions repair;
  repair.repair_thermal_index = true;
  const auto t = build_table(raw, repair);
  EXPECT_EQ(t->report.find("thermal_index_repair"), nullptr) << t->report.str();
  EXPECT_NE(t->report.find("thermal_index"), nullptr) << t->report.str();
}

// The reduced SFHo node (1.377e-4, T_min, Ye 0.0721): p 8.8 % up, index 158 -> 1.1, the check passes.
TEST(EOSChecks, SharedReducedSFHoThermalIndexRepair) {
  const std::string path = eos_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
  REQUIRE_TABLE(path);
  ReadOptions o;
  o.sc_cs2 = Cs2Convention::relativistic;
  o.build.repair_thermal_index = true;
  auto t = load_table(path, o);
  EXPECT_EQ(t->report.find("thermal_index"), nullptr) << t->report.str();
  const CheckIssue* w = t->report.find("thermal_index_repair");
  ASSERT_NE(w, nullptr) << t->report.str();
  EXPECT_EQ(w->count, 1u) << w->message;
  EXPECT_NE(w->message.find("(irho, iT, iYe) = (34, 0, 2)"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("(code, 8.814 %)"), std::string::npos) << w->message;
  EXPECT_NE(w->message.find("158.3 -> 1.116"), std::string::npos) << w->message;
}
