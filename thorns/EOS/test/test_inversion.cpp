// eps -> T: round trips, rules 8 and 9, the temperature guess, both methods.
#include <random>

#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "eos_test_util.hpp"

using namespace remnant::eos;

namespace {

const std::string kSC = eos_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");

struct RoundTrip {
  double worst = 0;
  std::size_t tested = 0, ill_conditioned = 0;
  double evals_per_inversion = 0;
};

// Random (rho, T, Ye) inside the table -> eps -> T. Points where double-precision eps cannot
// determine T to 1e-10 (d ln(eps + shift)/d ln T below 1e-5: the cold degenerate corner, where
// rounding eps alone moves T by more than 1e-10) are counted, not tested.
RoundTrip round_trip(const Tabulated<CountCalls>& eos, InversionMethod m, bool with_guess) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  const Bounds& b = eos.bounds();
  const double shift = eos.table().eps_shift;
  RoundTrip r;
  std::uint64_t evals = 0;
  for (int k = 0; k < 20000; ++k) {
    const double rho = b.rho_min * std::pow(b.rho_max / b.rho_min, u(rng));
    const double T = b.T_min * std::pow(b.T_max / b.T_min, 0.001 + 0.998 * u(rng));
    const double ye = b.ye_min + (b.ye_max - b.ye_min) * u(rng);
    const double e = eos.eps(rho, T, ye);
    const double slope = (std::log(eos.eps(rho, T * 1.001, ye) + shift) - std::log(e + shift)) / std::log(1.001);
    if (slope < 1e-5) {
      ++r.ill_conditioned;
      continue;
    }
    const std::uint64_t c0 = eos.counter().count();
    const Inversion inv = eos.temperature(rho, e, ye, with_guess ? T * 1.05 : 0.0, m);
    evals += eos.counter().count() - c0;
    EXPECT_EQ(inv.flags, 0u);
    r.worst = std::max(r.worst, std::abs(inv.T - T) / T);
    ++r.tested;
  }
  r.evals_per_inversion = double(evals) / r.tested;
  return r;
}

}  // namespace

TEST(EOSInversion, RoundTripExactMethod) {
  REQUIRE_TABLE(kSC);
  Tabulated<CountCalls> eos(load_table(kSC));
  for (bool guess : {false, true}) {
    const RoundTrip r = round_trip(eos, InversionMethod::exact, guess);
    std::printf("[ exact%s ] worst rel. T error %.2e over %zu points (%zu ill-conditioned skipped), %.2f table evals each\n",
                guess ? "+guess" : "", r.worst, r.tested, r.ill_conditioned, r.evals_per_inversion);
    EXPECT_LT(r.worst, 1e-10);
    EXPECT_LT(r.ill_conditioned, r.tested / 50);
  }
}

TEST(EOSInversion, RoundTripBrent) {
  REQUIRE_TABLE(kSC);
  Tabulated<CountCalls> eos(load_table(kSC));
  for (bool guess : {false, true}) {
    const RoundTrip r = round_trip(eos, InversionMethod::brent, guess);
    std::printf("[ brent%s ] worst rel. T error %.2e over %zu points, %.2f table evals each\n",
                guess ? "+guess" : "", r.worst, r.tested, r.evals_per_inversion);
    EXPECT_LT(r.worst, 1e-10);
  }
}

TEST(EOSInversion, Rules8And9) {
  REQUIRE_TABLE(kSC);
  Tabulated<> eos(load_table(kSC));
  const double rho = 1e-6, ye = 0.2;  // code units, inside the table
  const EpsRange er = eos.eps_range(rho, ye);
  ASSERT_LT(er.low, er.high);
  for (auto m : {InversionMethod::exact, InversionMethod::brent}) {
    Inversion lo = eos.temperature(rho, er.low - 1e-3, ye, 0, m);
    EXPECT_EQ(lo.flags, kInvBelowEpsLow);
    EXPECT_EQ(lo.T, eos.bounds().T_min);
    EXPECT_NEAR(lo.eps, er.low, 1e-15);
    Inversion hi = eos.temperature(rho, er.high * 2, ye, 0, m);
    EXPECT_EQ(hi.flags, kInvAboveEpsHigh);
    EXPECT_EQ(hi.T, eos.bounds().T_max);
    EXPECT_NEAR(hi.eps / er.high, 1.0, 1e-14);
    EXPECT_EQ(eos.temperature(rho, std::nan(""), ye, 0, m).flags, kInvBelowEpsLow);  // never a NaN T
  }
  // Outside the table in rho or Ye: flagged, evaluated at the edge.
  EXPECT_TRUE(eos.temperature(1e3, 0.1, ye).flags & kInvRhoClamped);
  EXPECT_TRUE(eos.temperature(rho, 0.01, 0.9).flags & kInvYeClamped);
}

TEST(EOSInversion, ThermoFromEpsCarriesTheGuess) {
  REQUIRE_TABLE(kSC);
  Tabulated<CountCalls> eos(load_table(kSC));
  const double rho = 1e-4, ye = 0.1;
  double T = 0;  // no guess yet
  std::uint32_t flags = 1;
  const double e = eos.eps(rho, 5.0, ye);
  const Thermo th = eos.thermo_from_eps(rho, e, ye, T, &flags);
  EXPECT_EQ(flags, 0u);
  EXPECT_NEAR(T, 5.0, 5e-10);
  EXPECT_DOUBLE_EQ(th.eps, e);
  EXPECT_NEAR(th.press / eos.press(rho, 5.0, ye), 1.0, 1e-9);
  // A nearby state with the carried guess needs fewer evaluations than a cold start.
  const double e2 = eos.eps(rho, 5.05, ye);
  const auto c0 = eos.counter().count();
  eos.temperature(rho, e2, ye, T);
  const auto with_guess = eos.counter().count() - c0;
  eos.temperature(rho, e2, ye, 0);
  const auto without = eos.counter().count() - c0 - with_guess;
  EXPECT_LT(with_guess, without);
}
