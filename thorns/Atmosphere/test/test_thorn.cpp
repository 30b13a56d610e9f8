// The thorn binding: thorn.yaml parses; Atmosphere_Startup reads the EOS service and publishes
// service "atmosphere".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <remnant/context.hpp>
#include <remnant/registrar.hpp>
#include <remnant_test/thorn_fixture.hpp>
#include <remnant/thorn_spec.hpp>

#include "Atmosphere/make_atmosphere.hpp"

void remnant_register_thorn_Atmosphere(remnant::ThornRegistrar&);

namespace {


remnant::ThornSpec spec() { return remnant::test::thorn_spec_from_source(REMNANT_SOURCE_DIR, "Atmosphere"); }

}  // namespace

TEST(AtmosphereThorn, ThornYamlParsesAndRunsAfterEosStartup) {
  remnant::test::expect_startup_provider(spec(), "Atmosphere", "atmosphere", "EOS_Startup", remnant_register_thorn_Atmosphere);
}

TEST(AtmosphereThorn, StartupPublishesTheAtmosphere) {
  remnant::test::ThornContext thorn(spec(), remnant_register_thorn_Atmosphere);
  auto& [params, vars, ctx, r] = thorn;
  EXPECT_THROW(r.fns.at("Atmosphere_Startup")(ctx), remnant::RunError);  // no EOS service yet

  ctx.publish("eos", std::make_shared<remnant::eos::EOS>(remnant::eos::IdealGas<>(2.0)));
  params.set("Atmosphere", "rho_thr", 1e-12, {});
  params.set("Atmosphere", "xi", 0.5, {});
  r.fns.at("Atmosphere_Startup")(ctx);
  const auto& a = ctx.service<remnant::atmosphere::Atmosphere>("atmosphere");
  EXPECT_EQ(a.rho_thr, 1e-12);
  EXPECT_DOUBLE_EQ(a.rho, 0.5e-12);
  EXPECT_DOUBLE_EQ(a.press, 100 * a.rho * a.rho);
}
