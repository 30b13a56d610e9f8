// Each of the ten error-policy rules, triggered by a crafted state, on the reduced SFHo table; and
// the rules reported by the recovery itself, and their counts as grid diagnostics.
#include <cmath>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/error_policy.hpp"
#include "Con2Prim/recover.hpp"
#include "Con2Prim/report.hpp"
#include "Con2Prim/state_builder.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "EOS/units.hpp"
#include "c2p_test_util.hpp"

using namespace remnant::con2prim;
namespace eos = remnant::eos;

namespace {

const std::string kTable = c2p_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
const double kRho = 1e12 * remnant::units::rho_cgs_to_code;  // above the rule-10 limit
const double kRhoLow = 1e9 * remnant::units::rho_cgs_to_code;

class Policy : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kTable)) GTEST_SKIP() << "EOS table not found: " << kTable;
    e = std::make_unique<eos::Tabulated<>>(eos::load_table(kTable));
  }
  // A valid state at rest at (rho, T = 5 MeV, Ye = 0.1).
  Primitives state(double rho = kRho) const {
    return make_state(*e, Metric3::flat(), rho, 5.0, 0.1, 1.0, 0.0, {1, 0, 0}, {0, 0, 1});
  }
  std::uint32_t apply(Primitives& p, ThermoInput in) const { return apply_error_policy(*e, ps, p, in); }
  const eos::Bounds& b() const { return e->bounds(); }

  std::unique_ptr<eos::Tabulated<>> e;
  PolicySettings ps;
};

}  // namespace

TEST_F(Policy, ValidStateFiresNothing) {
  for (ThermoInput in : {ThermoInput::eps, ThermoInput::temperature, ThermoInput::consistent}) {
    Primitives p = state();
    const Primitives before = p;
    EXPECT_EQ(apply(p, in), 0u);
    EXPECT_DOUBLE_EQ(p.rho, before.rho);
    EXPECT_NEAR(p.T, before.T, 1e-10 * before.T);
  }
}

TEST_F(Policy, Rule1RhoAboveMaxIsFatal) {
  Primitives p = state();
  p.rho = 2 * b().rho_max;
  const std::uint32_t r = apply(p, ThermoInput::consistent);
  EXPECT_TRUE(r & kRuleRhoAboveMax);
  EXPECT_TRUE(is_fatal(r));
}

TEST_F(Policy, Rule2EpsBelowMinIsRaised) {
  Primitives p = state();
  p.eps = b().eps_min - 1e-3;
  const std::uint32_t r = apply(p, ThermoInput::consistent);
  EXPECT_EQ(r, kRuleEpsBelowMin);
  EXPECT_EQ(p.eps, b().eps_min);
  EXPECT_FALSE(is_fatal(r));
}

TEST_F(Policy, Rule3EpsAboveMaxIsFatal) {
  Primitives p = state();
  p.eps = 2 * b().eps_max;
  const std::uint32_t r = apply(p, ThermoInput::consistent);
  EXPECT_TRUE(r & kRuleEpsAboveMax);
  EXPECT_TRUE(is_fatal(r));
}

TEST_F(Policy, Rule4TBelowMinIsRaised) {
  Primitives p = state();
  p.T = 0.5 * b().T_min;
  EXPECT_EQ(apply(p, ThermoInput::temperature), kRuleTBelowMin);
  EXPECT_EQ(p.T, b().T_min);
}

TEST_F(Policy, Rule5TAboveMaxIsFatal) {
  Primitives p = state();
  p.T = 2 * b().T_max;
  const std::uint32_t r = apply(p, ThermoInput::temperature);
  EXPECT_EQ(r, kRuleTAboveMax);
  EXPECT_TRUE(is_fatal(r));
}

TEST_F(Policy, Rules6And7ClampYe) {
  Primitives p = state();
  p.ye = b().ye_min / 2;
  EXPECT_EQ(apply(p, ThermoInput::temperature), kRuleYeBelowMin);
  EXPECT_EQ(p.ye, b().ye_min);
  p.ye = 1.5 * b().ye_max;
  EXPECT_EQ(apply(p, ThermoInput::temperature), kRuleYeAboveMax);
  EXPECT_EQ(p.ye, b().ye_max);
}

TEST_F(Policy, Rule8EpsBelowEpsLowGivesTMin) {
  Primitives p = state();
  const eos::EpsRange r = e->eps_range(p.rho, p.ye);
  p.eps = r.low - 1e-6 * std::abs(r.low);
  ASSERT_GE(p.eps, b().eps_min);  // rule 2 stays quiet
  EXPECT_EQ(apply(p, ThermoInput::eps), kRuleEpsBelowLow);
  EXPECT_EQ(p.T, b().T_min);
  EXPECT_DOUBLE_EQ(p.eps, r.low);
}

TEST_F(Policy, Rule9EpsAboveEpsHighGivesTMax) {
  Primitives p = state();
  const eos::EpsRange r = e->eps_range(p.rho, p.ye);
  p.eps = r.high * (1 + 1e-3);
  ASSERT_LE(p.eps, b().eps_max);
  EXPECT_EQ(apply(p, ThermoInput::eps), kRuleEpsAboveHigh);
  EXPECT_EQ(p.T, b().T_max);
  EXPECT_DOUBLE_EQ(p.eps, r.high);
}

TEST_F(Policy, Rule10LimitsWOnlyAtLowDensityKeepingD) {
  ps.W_max = 10;
  Primitives p = make_state(*e, Metric3::flat(), kRhoLow, 5.0, 0.1, 50.0, 0.0, {0.6, 0.8, 0}, {0, 0, 1});
  const double D = p.rho * p.W;
  EXPECT_EQ(apply(p, ThermoInput::consistent), kRuleWAboveMax);
  EXPECT_EQ(p.W, 10.0);
  EXPECT_NEAR(p.rho * p.W, D, 1e-14 * D);
  EXPECT_NEAR(std::sqrt(dot(p.v, p.v)), std::sqrt(1 - 1 / 100.0), 1e-14);
  EXPECT_NEAR(p.v[1] / p.v[0], 0.8 / 0.6, 1e-12);  // direction kept
  Primitives dense = make_state(*e, Metric3::flat(), kRho, 5.0, 0.1, 50.0, 0.0, {1, 0, 0}, {0, 0, 1});
  EXPECT_EQ(apply(dense, ThermoInput::consistent), 0u);
  EXPECT_EQ(dense.W, 50.0);
}

// --- the same rules as reported by the recovery (step i, the inversion inside iv, step v) -------

namespace {
remnant::atmosphere::Atmosphere thin_atmosphere() {
  remnant::atmosphere::Atmosphere a;
  a.rho_thr = 1e-300;
  return a;
}
}  // namespace

TEST_F(Policy, RecoveryReportsYeClampsFromDYe) {
  const Metric3 g = Metric3::flat();
  Settings s;
  Primitives p = state();
  Conserved c = prim_to_cons(p, g);
  c.DYe = c.D * 0.9;  // Ye = 0.9 > Ye_max
  Primitives got;
  const Report rep = recover(*e, s, thin_atmosphere(), g, c, got);
  EXPECT_EQ(rep.status, Status::ok);
  EXPECT_TRUE(rep.rules & kRuleYeAboveMax);
  EXPECT_EQ(got.ye, b().ye_max);
  EXPECT_DOUBLE_EQ(c.DYe, c.D * b().ye_max);  // conserved variables recomputed from the clamp
}

TEST_F(Policy, RecoveryReportsRule8ForTooLittleEnergy) {
  const Metric3 g = Metric3::flat();
  Settings s;
  Primitives p = state();
  const eos::EpsRange r = e->eps_range(p.rho, p.ye);
  Conserved c = prim_to_cons(p, g);
  c.tau -= c.D * (p.eps - r.low) + 1e-3 * c.D;  // below the cold eps at this density
  Primitives got;
  const Report rep = recover(*e, s, thin_atmosphere(), g, c, got);
  EXPECT_EQ(rep.status, Status::ok);
  EXPECT_TRUE(rep.rules & kRuleEpsBelowLow);
  EXPECT_EQ(got.T, b().T_min);
  EXPECT_NEAR(got.eps, e->eps_range(got.rho, got.ye).low, 1e-12);
}

TEST_F(Policy, RecoveryReportsRule1ForTooDenseMatter) {
  const Metric3 g = Metric3::flat();
  Settings s;
  Primitives p = state(b().rho_max);
  p.rho = 3 * b().rho_max;
  Conserved c = prim_to_cons(p, g);
  Primitives got;
  const Report rep = recover(*e, s, thin_atmosphere(), g, c, got);
  EXPECT_TRUE(rep.rules & kRuleRhoAboveMax);
  EXPECT_TRUE(rep.fatal());
  EXPECT_TRUE(std::isfinite(got.press));
}

TEST_F(Policy, RecoveryAppliesRule10KeepingD) {
  const Metric3 g = Metric3::flat();
  Settings s;
  s.policy.W_max = 20;
  const Primitives p = make_state(*e, g, kRhoLow, 5.0, 0.1, 80.0, 1e-2, {1, 1, 0}, {0, 1, 1});
  Conserved c = prim_to_cons(p, g);
  const double D = c.D;
  Primitives got;
  const Report rep = recover(*e, s, thin_atmosphere(), g, c, got);
  EXPECT_EQ(rep.status, Status::ok);
  EXPECT_EQ(rep.rules, kRuleWAboveMax);
  EXPECT_EQ(got.W, 20.0);
  EXPECT_NEAR(c.D, D, 1e-12 * D);
  EXPECT_NEAR(got.rho, D / 20, 1e-12 * D);
  EXPECT_NEAR(got.eps, e->eps(got.rho, got.T, got.ye), 1e-12);  // eps follows the new (rho, T, Ye)
}

TEST_F(Policy, DiagnosticsCountRulesAndStatuses) {
  Diagnostics d, other;
  Report a;
  a.rules = kRuleYeBelowMin | kRuleEpsBelowLow;
  a.iterations = 5;
  a.eos_calls = 40;
  Report f;
  f.rules = kRuleRhoAboveMax;
  f.status = Status::not_converged;
  f.iterations = 300;
  d.add(a);
  d.add(a);
  other.add(f);
  other.add_rules(kRuleTBelowMin);  // e.g. after reconstruction
  d.merge(other);
  EXPECT_EQ(d.cells, 3u);
  EXPECT_EQ(d.rules[5], 2u);   // rule 6
  EXPECT_EQ(d.rules[7], 2u);   // rule 8
  EXPECT_EQ(d.rules[0], 1u);   // rule 1
  EXPECT_EQ(d.rules[3], 1u);   // rule 4
  EXPECT_EQ(d.fatal_cells, 1u);
  EXPECT_EQ(d.count(Status::ok), 2u);
  EXPECT_EQ(d.count(Status::not_converged), 1u);
  EXPECT_EQ(d.max_iterations, 300);
  EXPECT_EQ(d.eos_calls, 80u);
  EXPECT_STREQ(rule_name(9), "10: W > W_max at rho <= W_max_rho_limit");
}
