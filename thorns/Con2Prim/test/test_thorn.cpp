// The thorn binding: thorn.yaml parses, and Con2Prim_Startup publishes the settings as "con2prim".
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <remnant/context.hpp>
#include <remnant/registrar.hpp>
#include <remnant_test/thorn_fixture.hpp>
#include <remnant/thorn_spec.hpp>

#include "Con2Prim/settings.hpp"
#include "EOS/units.hpp"
#include "c2p_test_util.hpp"

void remnant_register_thorn_Con2Prim(remnant::ThornRegistrar&);

namespace {


remnant::ThornSpec spec() { return remnant::test::thorn_spec_from_source(REMNANT_SOURCE_DIR, "Con2Prim"); }

}  // namespace

TEST(Con2PrimThorn, ThornYamlParsesAndDeclaresStartup) {
  remnant::test::expect_startup_provider(spec(), "Con2Prim", "con2prim", "Atmosphere_Startup", remnant_register_thorn_Con2Prim);
}

TEST(Con2PrimThorn, StartupPublishesTheSettings) {
  namespace c2p = remnant::con2prim;
  remnant::test::ThornContext thorn(spec(), remnant_register_thorn_Con2Prim);
  auto& [params, vars, ctx, r] = thorn;

  r.fns.at("Con2Prim_Startup")(ctx);
  const c2p::Settings& d = ctx.service<c2p::Settings>("con2prim");
  EXPECT_EQ(d.method, c2p::Method::kastaun);
  EXPECT_EQ(d.tolerance, 5e-9);
  EXPECT_EQ(d.eps_to_T, remnant::eos::InversionMethod::exact);
  EXPECT_TRUE(d.secant_polish);
  // The default is the paper's 1e11 g/cm^3, written in code units.
  EXPECT_NEAR(d.policy.rho_W_limit, 1e11 * remnant::units::rho_cgs_to_code, 1e-4 * d.policy.rho_W_limit);

  params.set("Con2Prim", "method", std::string("palenzuela"), {});
  params.set("Con2Prim", "tolerance", 1e-10, {});
  params.set("Con2Prim", "max_iterations", std::int64_t(40), {});
  params.set("Con2Prim", "eps_to_T", std::string("brent"), {});
  params.set("Con2Prim", "W_max", 50.0, {});
  params.set("Con2Prim", "W_max_rho_limit", 0.25, {});
  r.fns.at("Con2Prim_Startup")(ctx);
  const c2p::Settings& s = ctx.service<c2p::Settings>("con2prim");
  EXPECT_EQ(s.method, c2p::Method::palenzuela);
  EXPECT_EQ(s.tolerance, 1e-10);
  EXPECT_EQ(s.max_iterations, 40);
  EXPECT_EQ(s.eps_to_T, remnant::eos::InversionMethod::brent);
  EXPECT_EQ(s.policy.W_max, 50.0);
  // Code units, as Atmosphere::rho_thr: a dimensionless problem's 0.25 is 0.25 (it was taken as g/cm^3,
  // 4e-19 in code units, so that rule 10 silently never fired at densities ~1).
  EXPECT_EQ(s.policy.rho_W_limit, 0.25);
}

TEST(Con2PrimThorn, Rule10ThatCanNeverApplyIsNamed) {
  namespace c2p = remnant::con2prim;
  c2p::PolicySettings p;
  p.W_max = 100;
  p.rho_W_limit = 1e-7;
  EXPECT_EQ(c2p::rule10_never_applies(p, 1e-10), "");
  EXPECT_EQ(c2p::rule10_never_applies(p, 1e-7), "");
  const std::string why = c2p::rule10_never_applies(p, 1e-6);
  EXPECT_NE(why.find("Con2Prim::W_max_rho_limit = 1e-07 (code units"), std::string::npos) << why;
  EXPECT_NE(why.find("below Atmosphere::rho_thr = 1e-06"), std::string::npos) << why;
  EXPECT_NE(why.find("rule 10 (W > W_max = 100) can never apply"), std::string::npos) << why;
}
