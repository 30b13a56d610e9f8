// prim -> cons -> prim round trips on a real tabulated EOS (the reduced SFHo table): random
// magnetised states over the whole table, W up to 100, b^2/2p up to 1e4, random near-flat metrics.
#include <cstdio>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/recover.hpp"
#include "Con2Prim/state_builder.hpp"
#include "EOS/counter.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "c2p_test_util.hpp"

using namespace remnant::con2prim;
namespace eos = remnant::eos;

namespace {

const std::string kTable = c2p_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");

// No atmosphere inside the table and no W limit: the round trip tests the recovery alone.
remnant::atmosphere::Atmosphere no_atmosphere() {
  remnant::atmosphere::Atmosphere a;
  a.rho_thr = 1e-300;
  return a;
}

struct Worst {
  double err = 0;
  std::string what;
};

struct RoundTripStats {
  double max_rho = 0, max_v = 0, max_eps = 0, max_ye = 0;
  int failures = 0, bad = 0, n = 0;
  double eos_calls = 0, iterations = 0;
  Worst worst;
};

template <class E>
RoundTripStats round_trips(const E& eos, Method method, int n, double W_hi, double b2p_hi, unsigned seed,
                           double tol_check) {
  Settings s;
  s.method = method;
  s.policy.W_max = 1e300;
  const auto atm = no_atmosphere();
  const eos::Bounds& b = eos.bounds();
  c2p_test::Randomiser R(seed);
  RoundTripStats st;
  for (int k = 0; k < n; ++k) {
    const Metric3 g = R.metric();
    const double rho = R.log_uniform(b.rho_min, b.rho_max), T = R.log_uniform(b.T_min, b.T_max);
    const double ye = R.uniform(b.ye_min, b.ye_max), W = R.log_uniform(1.0, W_hi);
    const double b2p = k % 10 == 0 ? 0.0 : R.log_uniform(1e-6, b2p_hi);
    const Primitives orig = make_state(eos, g, rho, T, ye, W, b2p, R.direction(), R.direction());
    Conserved c = prim_to_cons(orig, g);
    Primitives got;
    const Report rep = recover(eos, s, atm, g, c, got);
    ++st.n;
    st.eos_calls += double(rep.eos_calls);
    st.iterations += rep.iterations;
    if (rep.status != Status::ok) {
      ++st.failures;
      continue;
    }
    const double er = c2p_test::rel_err(got.rho, orig.rho), ev = c2p_test::vec_rel_err(got.v, orig.v);
    // eps relative, above the round-off floor of the conserved variables (c2p_test::eps_floor)
    const double ee = tol_check * c2p_test::eps_err(got.eps, orig.eps, tol_check, c2p_test::eps_floor(orig, g));
    const double ey = c2p_test::rel_err(got.ye, orig.ye);
    st.max_rho = std::max(st.max_rho, er);
    st.max_v = std::max(st.max_v, ev);
    st.max_eps = std::max(st.max_eps, ee);
    st.max_ye = std::max(st.max_ye, ey);
    const double e = std::max({er, ev, ee, ey});
    if (e > tol_check) ++st.bad;
    if (e > st.worst.err) {
      char buf[400];
      std::snprintf(buf, sizeof buf,
                    "rho=%.3e T=%.3e Ye=%.3f W=%.3e b2/2p=%.3e eps=%.6e: err rho %.2e v %.2e eps %.2e ye %.2e, "
                    "%d iterations",
                    rho, T, ye, W, b2p, orig.eps, er, ev, ee, ey, rep.iterations);
      st.worst = {e, buf};
    }
  }
  return st;
}

void print(const char* name, const RoundTripStats& st) {
  std::printf("[ %s ] %d states: max rel err rho %.2e v %.2e eps %.2e (above round-off) Ye %.2e; %d above tolerance, %d failed; "
              "mean %.1f iterations, %.1f EOS calls\n  worst: %s\n",
              name, st.n, st.max_rho, st.max_v, st.max_eps, st.max_ye, st.bad, st.failures, st.iterations / st.n,
              st.eos_calls / st.n, st.worst.what.c_str());
}

}  // namespace

TEST(Con2PrimRoundTrip, KastaunRecoversRandomMagnetisedStatesTo1em8) {
  REQUIRE_TABLE(kTable);
  eos::Tabulated<eos::CountCalls> e(eos::load_table(kTable));
  const RoundTripStats st = round_trips(e, Method::kastaun, 4000, 100.0, 1e4, 1234, 1e-8);
  print("kastaun", st);
  EXPECT_EQ(st.failures, 0);
  EXPECT_EQ(st.bad, 0) << st.worst.what;
  EXPECT_LT(st.eos_calls / st.n, 135.8);  // the paper's mean on LS220
}

TEST(Con2PrimRoundTrip, PalenzuelaRecoversModeratelyMagnetisedStates) {
  REQUIRE_TABLE(kTable);
  eos::Tabulated<eos::CountCalls> e(eos::load_table(kTable));
  const RoundTripStats st = round_trips(e, Method::palenzuela, 2000, 10.0, 1.0, 99, 1e-8);
  print("palenzuela", st);
  EXPECT_EQ(st.failures, 0);
  EXPECT_EQ(st.bad, 0) << st.worst.what;
}

TEST(Con2PrimRoundTrip, BrentInversionGivesTheSameRoot) {
  REQUIRE_TABLE(kTable);
  eos::Tabulated<> e(eos::load_table(kTable));
  const auto atm = no_atmosphere();
  Settings exact, brent;
  brent.eps_to_T = eos::InversionMethod::brent;
  c2p_test::Randomiser R(7);
  const eos::Bounds& b = e.bounds();
  for (int k = 0; k < 300; ++k) {
    const Metric3 g = R.metric();
    const Primitives orig = make_state(e, g, R.log_uniform(b.rho_min, b.rho_max), R.log_uniform(b.T_min, b.T_max),
                                       R.uniform(b.ye_min, b.ye_max), R.log_uniform(1, 10), R.log_uniform(1e-4, 10),
                                       R.direction(), R.direction());
    Conserved c1 = prim_to_cons(orig, g), c2 = c1;
    Primitives p1, p2;
    ASSERT_EQ(recover(e, exact, atm, g, c1, p1).status, Status::ok);
    ASSERT_EQ(recover(e, brent, atm, g, c2, p2).status, Status::ok);
    EXPECT_LT(c2p_test::rel_err(p2.rho, p1.rho), 1e-9);
    EXPECT_LT(c2p_test::rel_err(p2.T, p1.T), 1e-7);
  }
}

TEST(Con2PrimRoundTrip, RecomputedConservedMatchTheInput) {
  REQUIRE_TABLE(kTable);
  eos::Tabulated<> e(eos::load_table(kTable));
  const auto atm = no_atmosphere();
  Settings s;
  c2p_test::Randomiser R(11);
  const eos::Bounds& b = e.bounds();
  for (int k = 0; k < 300; ++k) {
    const Metric3 g = R.metric();
    const Primitives orig = make_state(e, g, R.log_uniform(1e-10, b.rho_max), R.log_uniform(b.T_min, b.T_max),
                                       R.uniform(b.ye_min, b.ye_max), R.log_uniform(1, 10), R.log_uniform(1e-4, 10),
                                       R.direction(), R.direction());
    const Conserved in = prim_to_cons(orig, g);
    Conserved c = in;
    Primitives p;
    ASSERT_EQ(recover(e, s, atm, g, c, p).status, Status::ok);
    const double scale = in.tau + in.D;
    EXPECT_LT(std::abs(c.D - in.D) / in.D, 1e-8);
    EXPECT_LT(std::abs(c.tau - in.tau) / scale, 1e-8);
    for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(c.S[i] - in.S[i]) / scale, 1e-8);
    EXPECT_DOUBLE_EQ(c.DYe / c.D, p.ye);
  }
}
