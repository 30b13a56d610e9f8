// Recovery with the analytic EOS through the same template: ideal gas, polytrope, hybrid. For the
// unmagnetised ideal gas the result is compared with an independent exact inversion (bisection in
// long double on the pressure, from the definitions of D, S, tau only).
#include <cmath>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/recover.hpp"
#include "Con2Prim/state_builder.hpp"
#include "EOS/counter.hpp"
#include "EOS/hybrid.hpp"
#include "EOS/ideal_gas.hpp"
#include "EOS/polytrope.hpp"
#include "c2p_test_util.hpp"

using namespace remnant::con2prim;
namespace eos = remnant::eos;

namespace {

remnant::atmosphere::Atmosphere tiny_atmosphere() {
  remnant::atmosphere::Atmosphere a;
  a.rho_thr = 1e-300;
  return a;
}

// Ideal gas, B = 0: p solves p = (Gamma-1) rho eps with v = |S|/(tau + D + p), W = 1/sqrt(1 - v^2),
// rho = D/W, rho h = (tau + D + p)/W^2; bisection in long double. eps is compared above the round-off
// floor of the double-precision conserved variables (c2p_test::eps_floor), which bounds any method.
struct Exact {
  long double rho, eps, press, W;
};
Exact exact_ideal_gas(long double gamma, long double D, long double S, long double tau) {
  auto residual = [&](long double p, Exact& e) {
    const long double E = tau + D + p;  // rho h W^2
    const long double v2 = S * S / (E * E);
    e.W = 1 / std::sqrt(1 - v2);
    e.rho = D / e.W;
    const long double rho_h = E / (e.W * e.W);  // rho + rho eps + p
    e.eps = (rho_h - p) / e.rho - 1;
    e.press = p;
    return (gamma - 1) * e.rho * e.eps - p;
  };
  long double lo = std::max<long double>(0, S - tau - D) * (1 + 1e-18L), hi = 10 * (tau + D);
  Exact e{};
  for (int i = 0; i < 300; ++i) {
    const long double mid = 0.5L * (lo + hi);
    (residual(mid, e) > 0 ? lo : hi) = mid;
  }
  residual(0.5L * (lo + hi), e);
  return e;
}

template <class E>
void expect_round_trips(const E& e, Method m, double W_hi, double b2p_hi, bool barotropic, unsigned seed) {
  Settings s;
  s.method = m;
  s.policy.W_max = 1e300;
  const auto atm = tiny_atmosphere();
  c2p_test::Randomiser R(seed);
  for (int k = 0; k < 500; ++k) {
    const Metric3 g = R.metric();
    const double T = barotropic ? 0.0 : R.log_uniform(0.01, 100.0);
    const Primitives orig = make_state(e, g, R.log_uniform(1e-10, 1e-2), T, 0.3, R.log_uniform(1, W_hi),
                                       k % 5 ? R.log_uniform(1e-6, b2p_hi) : 0.0, R.direction(), R.direction());
    Conserved c = prim_to_cons(orig, g);
    Primitives got;
    const Report rep = recover(e, s, atm, g, c, got);
    ASSERT_EQ(rep.status, Status::ok);
    EXPECT_EQ(rep.rules, 0u) << "no policy rule should fire for a valid state";
    EXPECT_LT(c2p_test::rel_err(got.rho, orig.rho), 1e-8);
    EXPECT_LT(c2p_test::vec_rel_err(got.v, orig.v), 1e-8);
    const double floor = c2p_test::eps_floor(orig, g);
    EXPECT_LE(c2p_test::eps_err(got.eps, orig.eps, 1e-8, floor), 1.0);
    EXPECT_LE(c2p_test::eps_err(got.press / got.rho, orig.press / orig.rho, 1e-8, floor), 1.0);
    EXPECT_LT(c2p_test::rel_err(got.W, orig.W), 1e-8);
  }
}

}  // namespace

TEST(Con2PrimAnalytic, IdealGasAgreesWithExactInversion) {
  const double gamma = 5.0 / 3.0;
  eos::IdealGas<> gas(gamma);
  Settings s;
  const auto atm = tiny_atmosphere();
  c2p_test::Randomiser R(5);
  const Metric3 g = Metric3::flat();
  for (int k = 0; k < 300; ++k) {
    const Primitives orig = make_state(gas, g, R.log_uniform(1e-10, 1e-2), R.log_uniform(0.01, 100.0), 0.3,
                                       R.log_uniform(1, 100), 0.0, R.direction(), R.direction());
    Conserved c = prim_to_cons(orig, g);
    long double S2 = 0;  // in long double: |S| rounded to double would cost ~1e-16 W^2 / eps in eps
    for (double Si : c.S) S2 += (long double)Si * Si;
    const long double S = std::sqrt(S2);
    const Exact ex = exact_ideal_gas(gamma, c.D, S, c.tau);
    for (Method m : {Method::kastaun, Method::palenzuela}) {
      s.method = m;
      Conserved cm = c;
      Primitives got;
      ASSERT_EQ(recover(gas, s, atm, g, cm, got).status, Status::ok);
      EXPECT_LT(c2p_test::rel_err(got.rho, double(ex.rho)), 1e-9) << to_string(m);
      const double floor = c2p_test::eps_floor(orig, g);
      EXPECT_LE(c2p_test::eps_err(got.eps, double(ex.eps), 1e-9, floor), 1.0) << to_string(m);
      EXPECT_LE(c2p_test::eps_err(got.press / got.rho, double(ex.press / ex.rho), 1e-9, floor), 1.0) << to_string(m);
      EXPECT_LT(c2p_test::rel_err(got.W, double(ex.W)), 1e-9) << to_string(m);
    }
  }
}

TEST(Con2PrimAnalytic, IdealGasMagnetisedRoundTrips) {
  expect_round_trips(eos::IdealGas<>(2.0), Method::kastaun, 100, 1e4, false, 21);
  expect_round_trips(eos::IdealGas<>(4.0 / 3.0), Method::kastaun, 100, 1e4, false, 22);
  expect_round_trips(eos::IdealGas<>(2.0), Method::palenzuela, 10, 1.0, false, 23);
}

TEST(Con2PrimAnalytic, HybridRoundTrips) {
  eos::Hybrid<> hyb(eos::PiecewisePolytrope(100.0, {2.0}, {}), 1.75);
  expect_round_trips(hyb, Method::kastaun, 100, 1e4, false, 31);
}

TEST(Con2PrimAnalytic, PolytropeRoundTripsAndIgnoresTau) {
  eos::Polytrope<> poly(100.0, 2.0);
  expect_round_trips(poly, Method::kastaun, 100, 1e4, true, 41);
  // A barotropic EOS takes eps from rho: a wrong tau does not change rho and v much, and no
  // rule 8/9 is reported for it.
  Settings s;
  const auto atm = tiny_atmosphere();
  const Metric3 g = Metric3::flat();
  const Primitives orig = make_state(poly, g, 1e-3, 0.0, 0.3, 1.5, 0.0, {1, 0, 0}, {0, 1, 0});
  Conserved c = prim_to_cons(orig, g);
  c.tau *= 1.0 + 1e-3;
  Primitives got;
  const Report rep = recover(poly, s, atm, g, c, got);
  EXPECT_EQ(rep.status, Status::ok);
  EXPECT_EQ(rep.rules, 0u);
  EXPECT_DOUBLE_EQ(got.eps, poly.eps(got.rho));
}

TEST(Con2PrimAnalytic, EosCallsAreCountedOnlyWithACountingEos) {
  const Metric3 g = Metric3::flat();
  const auto atm = tiny_atmosphere();
  Settings s;
  eos::IdealGas<eos::CountCalls> counted(2.0);
  eos::IdealGas<> plain(2.0);
  const Primitives orig = make_state(plain, g, 1e-4, 1.0, 0.3, 3.0, 0.1, {1, 0, 0}, {0, 1, 0});
  Conserved c1 = prim_to_cons(orig, g), c2 = c1;
  Primitives p;
  const Report a = recover(counted, s, atm, g, c1, p);
  const Report b = recover(plain, s, atm, g, c2, p);
  EXPECT_GT(a.eos_calls, 0u);
  EXPECT_EQ(a.eos_calls, counted.counter().count());
  EXPECT_EQ(b.eos_calls, 0u);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_GT(a.evaluations, a.iterations);
  EXPECT_GT(a.aux_iterations, 0);
}
