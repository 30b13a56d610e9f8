// Radial mode frequencies of BU0 (issue 20, item 1; CTest label `long`): the parfiles bu0_cow.yaml
// and bu0_dyn.yaml as shipped (640 cells, 10 ms), the oscillation seeded by truncation error alone.
// The peaks of the power spectrum of rho_c(t)/rho_c(0) - 1 near F, H1 and H2 must lie within 0.5 %
// of the perturbative frequencies, computed here by an independent radial-perturbation solver
// (radial_modes.hpp) for the same star (K = 100, Gamma = 2, rho_c = 1.28e-3):
//   Cowling (metric frozen): 2.6861, 4.5494, 6.3412 kHz;
//   full GR: 1.4425, 3.9541, 5.9150 kHz, which reproduces the published 1.442, 3.955, 5.916 kHz
//     (Font et al. 2002, PRD 65, 084024) and so checks the solver.
// The Cowling values quoted in the literature (2.706, 4.547, 6.320 kHz, Font, Stergioulas &
// Kokkotas 2000, MNRAS 313, 678) differ from the frozen-metric problem by -0.74 % in F; the code
// matches the frozen-metric values at every resolution (F -0.70 %, -0.74 %, -0.71 % against the
// literature at 320, 640, 1280 cells), so the literature F is not used.
// The spectrum is utils/plot_modes' (uniform resampling, mean removed, Hann window) evaluated as a
// continuous Fourier sum, its largest peak within 15 % of each reference refined by a parabola
// through log power.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "radial_modes.hpp"
#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;
constexpr double kTimeUnitMs = 4.925490947641267e-3;  // G M_sun / c^3 in ms

struct Series {
  std::vector<double> t_ms, y;
};

Series run(const std::string& parfile, std::vector<std::string> overrides) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/" + parfile;
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() / ("remnant_modes_" + std::to_string(::getpid()));
  o.overrides = std::move(overrides);
  o.overrides.push_back("Flesh::out_dir=" + out.string());
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  const auto& rows = sim.context().service<analysis::History>("Analysis::history").rows;
  Series s;
  for (const auto& r : rows) {
    s.t_ms.push_back(r.time * kTimeUnitMs);
    s.y.push_back(r.rho_c / rows.front().rho_c - 1);
  }
  std::filesystem::remove_all(out);
  return s;
}

// The series resampled uniformly (as many points), mean removed, Hann window.
struct Windowed {
  std::vector<double> t, y;
};
Windowed window(const Series& s) {
  const std::size_t n = s.t_ms.size();
  Windowed w;
  double mean = 0;
  std::size_t j = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = s.t_ms.front() + (s.t_ms.back() - s.t_ms.front()) * double(i) / double(n - 1);
    while (j + 2 < n && s.t_ms[j + 1] < t) ++j;
    const double a = (t - s.t_ms[j]) / (s.t_ms[j + 1] - s.t_ms[j]);
    w.t.push_back(t);
    w.y.push_back((1 - a) * s.y[j] + a * s.y[j + 1]);
    mean += w.y.back();
  }
  mean /= double(n);
  for (std::size_t i = 0; i < n; ++i)
    w.y[i] = (w.y[i] - mean) * 0.5 * (1 - std::cos(2 * std::numbers::pi * double(i) / double(n - 1)));
  return w;
}

double power(const Windowed& w, double f_khz) {
  double re = 0, im = 0;
  for (std::size_t i = 0; i < w.t.size(); ++i) {
    const double ph = 2 * std::numbers::pi * f_khz * w.t[i];
    re += w.y[i] * std::cos(ph), im += w.y[i] * std::sin(ph);
  }
  return re * re + im * im;
}

// The largest local maximum of the power within 15 % of f_ref (2 Hz scan, parabola in log power).
double peak_near(const Windowed& w, double f_ref) {
  const double df = 0.002;
  const int n = static_cast<int>(0.3 * f_ref / df);
  std::vector<double> lp(n + 1);
  for (int i = 0; i <= n; ++i) lp[i] = std::log(power(w, 0.85 * f_ref + i * df) + 1e-300);
  int best = -1;
  for (int i = 1; i < n; ++i)
    if (lp[i] > lp[i - 1] && lp[i] >= lp[i + 1] && (best < 0 || lp[i] > lp[best])) best = i;
  if (best < 0) return 0;
  const double a = lp[best - 1], b = lp[best], c = lp[best + 1], den = a - 2 * b + c;
  return 0.85 * f_ref + (best + (den != 0 ? 0.5 * (a - c) / den : 0.0)) * df;
}

struct Mode {
  const char* name;
  double reference_khz;
};

void expect_modes(const char* what, const Series& s, const std::vector<Mode>& modes, double tolerance) {
  ASSERT_GT(s.t_ms.size(), 100u);
  ASSERT_GT(s.t_ms.back(), 9.9) << what << ": the run stopped early";
  const Windowed w = window(s);
  for (const Mode& m : modes) {
    const double f = peak_near(w, m.reference_khz);
    std::printf("%s: %-2s %.4f kHz (perturbative %.3f, %+.2f %%)\n", what, m.name, f, m.reference_khz,
                100 * (f / m.reference_khz - 1));
    EXPECT_NEAR(f / m.reference_khz, 1.0, tolerance) << what << " " << m.name;
  }
}

std::vector<Mode> perturbative(bool full_gr) {
  const tov_test::RadialModes solver(100.0, 2.0, 1.28e-3, full_gr);
  const std::vector<double> f = solver.frequencies_khz(3, kTimeUnitMs);
  EXPECT_EQ(f.size(), 3u);
  return {{"F", f.at(0)}, {"H1", f.at(1)}, {"H2", f.at(2)}};
}

}  // namespace

// The solver against the published full-GR frequencies (their 4 digits): 1.4425, 3.9541, 5.9150.
TEST(ModeFrequencies, PerturbativeSolverReproducesPublishedFullGR) {
  const std::vector<Mode> m = perturbative(true);
  const double published[3] = {1.442, 3.955, 5.916};
  for (int i = 0; i < 3; ++i) {
    std::printf("full GR %-2s %.4f kHz (published %.3f)\n", m[i].name, m[i].reference_khz, published[i]);
    EXPECT_NEAR(m[i].reference_khz, published[i], 2e-3) << m[i].name;  // 3 decimals published
  }
}

// Measured: F 2.6861 (+0.00 %), H1 4.5489 (-0.01 %), H2 6.3428 (+0.02 %) kHz, the same at 320 and
// 1280 cells. Bound 0.1 % (5x): the gravitational source's 2 alpha S d_i psi / psi made 5 % weaker
// moves H1 by -0.16 % here, inside the 0.5 % the dynamical runs get.
TEST(ModeFrequencies, BU0CowlingAt640Cells) {
  expect_modes("BU0-cow", run("bu0_cow.yaml", {}), perturbative(false), 1e-3);
}

// Measured: F 1.4406 (-0.13 %), H1 3.9525 (-0.04 %), H2 5.9152 (+0.00 %) kHz.
TEST(ModeFrequencies, BU0DynamicalAt640Cells) {
  expect_modes("BU0-dyn", run("bu0_dyn.yaml", {}), perturbative(true), 5e-3);
}

namespace {
// The metric cadences (XCFC::solve_every > 1 with its extrapolation and updates) that the shipped
// cylindrical parfiles use, read from parfiles/, so that a parfile changed to another cadence is
// tested too.
std::vector<std::vector<std::string>> cylindrical_parfile_cadences() {
  std::vector<std::vector<std::string>> cadences;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(REMNANT_SOURCE_DIR) + "/parfiles")) {
    if (entry.path().extension() != ".yaml") continue;
    const YAML::Node par = YAML::LoadFile(entry.path().string());
    if (!par["Grid"] || par["Grid"]["coordinates"].as<std::string>("cartesian") != "cylindrical") continue;
    const YAML::Node x = par["XCFC"];
    if (!x || x["solve_every"].as<int>(1) <= 1) continue;
    std::vector<std::string> c = {"XCFC::solve_every=" + x["solve_every"].as<std::string>(),
                                  "XCFC::extrapolation=" + x["extrapolation"].as<std::string>("auto"),
                                  "XCFC::update_every=" + x["update_every"].as<std::string>("0")};
    if (std::find(cadences.begin(), cadences.end(), c) == cadences.end()) cadences.push_back(c);
  }
  return cadences;
}
}  // namespace

// BU0-dyn at each cadence of the cylindrical parfiles (issue 20, item 1), all three modes to 0.5 %.
// Measured with solve_every = 10 and quadratic extrapolation (the parfiles' choice): F 1.441
// (-0.08 %), H1 3.954 (-0.02 %), H2 5.913 (-0.05 %) kHz; linear extrapolation, the parfiles' former
// choice, put F at -0.53 %, outside the bound.
TEST(ModeFrequencies, BU0DynamicalAtTheCadenceOfTheCylindricalParfiles) {
  const auto cadences = cylindrical_parfile_cadences();
  ASSERT_FALSE(cadences.empty()) << "no cylindrical parfile with XCFC::solve_every > 1 found";
  for (const auto& c : cadences) {
    const std::string what = "BU0-dyn, " + c[0] + " " + c[1] + " " + c[2];
    expect_modes(what.c_str(), run("bu0_dyn.yaml", c), perturbative(true), 5e-3);
  }
}

namespace {
// rms of rho_c(t)/rho_c(0) - 1 about its mean over [a, b] ms.
double rms_between(const Series& s, double a, double b) {
  double sum = 0, sum2 = 0;
  int n = 0;
  for (std::size_t i = 0; i < s.t_ms.size(); ++i)
    if (s.t_ms[i] >= a && s.t_ms[i] <= b) sum += s.y[i], sum2 += s.y[i] * s.y[i], ++n;
  const double mean = sum / n;
  return std::sqrt(sum2 / n - mean * mean);
}
}  // namespace

// xi_eff = 1/50 with psi, alpha psi and beta re-solved every 5 steps between solves
// (XCFC::update_every, issue 21): measured F 1.4373 (-0.36 %), H1 3.9510 (-0.08 %), H2 5.9122
// (-0.05 %) kHz against the perturbative values, rms of the oscillation at 8-10 ms over 0.5-2.5 ms
// 0.579 (solving every step 0.576). Linear extrapolation alone gives F -9.1 % and 0.31 (damped)
// at this cadence. One more 10 ms run: about 7 s CPU.
TEST(ModeFrequencies, BU0DynamicalSolvingEvery50StepsUpdatingEvery5) {
  const Series s = run("bu0_dyn.yaml", {"XCFC::solve_every=50", "XCFC::update_every=5"});
  expect_modes("BU0-dyn, solve_every 50, update_every 5", s, perturbative(true), 5e-3);
  const double decay = rms_between(s, 8.0, 10.0) / rms_between(s, 0.5, 2.5);
  std::printf("BU0-dyn, solve_every 50, update_every 5: rms late/early %.3f (every step 0.576)\n", decay);
  EXPECT_NEAR(decay, 0.576, 0.05);
}
