// Load-time table checks: each problem is a TableError naming file and dataset, or a counted
// warning in the report. Never a crash or a silent NaN.
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
