// Bad input never gives NaN output: NaN/inf or negative D gives a flagged atmosphere cell; D below
// the threshold gives an atmosphere cell; random garbage gives finite primitives and conserved.
#include <cmath>
#include <limits>

#include "Atmosphere/make_atmosphere.hpp"
#include "Con2Prim/recover.hpp"
#include "Con2Prim/state_builder.hpp"
#include "EOS/ideal_gas.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "c2p_test_util.hpp"

using namespace remnant::con2prim;
namespace eos = remnant::eos;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

bool all_finite(const Primitives& p) {
  return std::isfinite(p.rho) && std::isfinite(p.eps) && std::isfinite(p.press) && std::isfinite(p.T) &&
         std::isfinite(p.ye) && std::isfinite(p.W) && std::isfinite(p.cs2) && std::isfinite(p.v[0]) &&
         std::isfinite(p.v[1]) && std::isfinite(p.v[2]) && std::isfinite(p.B[0]) && std::isfinite(p.B[1]) &&
         std::isfinite(p.B[2]);
}
bool all_finite(const Conserved& c) {
  return std::isfinite(c.D) && std::isfinite(c.tau) && std::isfinite(c.DYe) && std::isfinite(c.S[0]) &&
         std::isfinite(c.S[1]) && std::isfinite(c.S[2]) && std::isfinite(c.B[0]) && std::isfinite(c.B[1]) &&
         std::isfinite(c.B[2]);
}

template <class E>
void expect_flagged_atmosphere(const E& e, const remnant::atmosphere::Atmosphere& atm, const Conserved& bad,
                               Status want, const char* what) {
  const Metric3 g = Metric3::flat();
  for (Method m : {Method::kastaun, Method::palenzuela}) {
    Settings s;
    s.method = m;
    Conserved c = bad;
    Primitives p;
    const Report rep = recover(e, s, atm, g, c, p);
    EXPECT_STREQ(to_string(rep.status), to_string(want)) << what << " (" << to_string(m) << ")";
    EXPECT_EQ(p.rho, atm.rho) << what;
    EXPECT_EQ(p.W, 1.0) << what;
    EXPECT_EQ(p.ye, atm.ye) << what;
    EXPECT_TRUE(all_finite(p)) << what;
    EXPECT_TRUE(all_finite(c)) << what;
  }
}

}  // namespace

TEST(Con2PrimInvalid, NaNInfAndNegativeDGiveFlaggedAtmosphere) {
  eos::IdealGas<> gas(2.0);
  remnant::atmosphere::AtmosphereConfig cfg;
  const auto atm = remnant::atmosphere::make_atmosphere(gas, cfg);
  const Primitives good = make_state(gas, Metric3::flat(), 1e-4, 1.0, 0.3, 2.0, 0.1, {1, 0, 0}, {0, 1, 0});
  const Conserved c0 = prim_to_cons(good, Metric3::flat());
  auto with = [&](auto change) {
    Conserved c = c0;
    change(c);
    return c;
  };
  expect_flagged_atmosphere(gas, atm, with([](Conserved& c) { c.D = kNaN; }), Status::invalid_input, "D = NaN");
  expect_flagged_atmosphere(gas, atm, with([](Conserved& c) { c.D = -1e-5; }), Status::invalid_input, "D < 0");
  expect_flagged_atmosphere(gas, atm, with([](Conserved& c) { c.D = kInf; }), Status::invalid_input, "D = inf");
  expect_flagged_atmosphere(gas, atm, with([](Conserved& c) { c.tau = kNaN; }), Status::invalid_input, "tau = NaN");
  expect_flagged_atmosphere(gas, atm, with([](Conserved& c) { c.S[1] = -kInf; }), Status::invalid_input, "S = -inf");
  expect_flagged_atmosphere(gas, atm, with([](Conserved& c) { c.DYe = kNaN; }), Status::invalid_input, "DYe = NaN");
  expect_flagged_atmosphere(gas, atm, with([](Conserved& c) { c.D = 0; }), Status::atmosphere, "D = 0");
  expect_flagged_atmosphere(gas, atm, with([](Conserved& c) { c.D = 0.5 * 1e-14; }), Status::atmosphere,
                            "D < D_thr");
}

TEST(Con2PrimInvalid, NaNMagneticFieldIsZeroed) {
  eos::IdealGas<> gas(2.0);
  const auto atm = remnant::atmosphere::make_atmosphere(gas, {});
  Conserved c = prim_to_cons(make_state(gas, Metric3::flat(), 1e-4, 1.0, 0.3, 2.0, 0.1, {1, 0, 0}, {0, 1, 0}),
                             Metric3::flat());
  c.B[2] = kNaN;
  Primitives p;
  const Report rep = recover(gas, Settings{}, atm, Metric3::flat(), c, p);
  EXPECT_EQ(rep.status, Status::ok);
  EXPECT_EQ(p.B[0], 0.0);
  EXPECT_EQ(p.B[2], 0.0);
  EXPECT_TRUE(all_finite(p));
  EXPECT_TRUE(all_finite(c));
}

TEST(Con2PrimInvalid, AtmosphereAfterRecoveryKeepsB) {
  eos::IdealGas<> gas(2.0);
  const auto atm = remnant::atmosphere::make_atmosphere(gas, {});
  // D above the threshold but rho = D/W below it.
  const Primitives orig = make_state(gas, Metric3::flat(), 0.5e-14, 1.0, 0.3, 5.0, 0.1, {1, 0, 0}, {0, 1, 0});
  Conserved c = prim_to_cons(orig, Metric3::flat());
  ASSERT_FALSE(atm.is_atmosphere(c.D));
  Primitives p;
  const Report rep = recover(gas, Settings{}, atm, Metric3::flat(), c, p);
  EXPECT_EQ(rep.status, Status::atmosphere);
  EXPECT_EQ(p.rho, atm.rho);
  EXPECT_EQ(p.v[0], 0.0);
  EXPECT_EQ(p.B[1], orig.B[1]);
  EXPECT_DOUBLE_EQ(c.D, atm.rho);
  EXPECT_EQ(c.S[0], 0.0);
}

TEST(Con2PrimInvalid, RandomGarbageNeverGivesNaN) {
  const std::string table = c2p_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
  REQUIRE_TABLE(table);
  eos::Tabulated<> e(eos::load_table(table));
  const auto atm = remnant::atmosphere::make_atmosphere(e, {});
  c2p_test::Randomiser R(17);
  auto any = [&](double scale) { return (R.uniform(0, 1) < 0.5 ? -1 : 1) * R.log_uniform(1e-30, scale); };
  int statuses[kNumStatus] = {};
  for (int k = 0; k < 3000; ++k) {
    const Metric3 g = R.metric();
    Conserved c;
    c.D = R.uniform(0, 1) < 0.1 ? -R.log_uniform(1e-20, 1) : R.log_uniform(1e-20, 1e-1);
    for (int i = 0; i < 3; ++i) c.S[i] = any(10), c.B[i] = any(10);
    c.tau = any(10);
    c.DYe = c.D * R.uniform(-0.5, 1.5);
    for (Method m : {Method::kastaun, Method::palenzuela}) {
      Settings s;
      s.method = m;
      Conserved cm = c;
      Primitives p;
      const Report rep = recover(e, s, atm, g, cm, p);
      ++statuses[int(rep.status)];
      ASSERT_TRUE(all_finite(p)) << to_string(m) << " " << k;
      ASSERT_TRUE(all_finite(cm)) << to_string(m) << " " << k;
      ASSERT_GE(p.W, 1.0);
      ASSERT_LT(g.norm2_up(p.v), 1.0);
    }
  }
  std::printf("[ garbage ] statuses:");
  for (int i = 0; i < kNumStatus; ++i) std::printf(" %s %d", to_string(Status(i)), statuses[i]);
  std::printf("\n");
  EXPECT_GT(statuses[int(Status::invalid_input)], 0);
  EXPECT_GT(statuses[int(Status::atmosphere)], 0);
}
