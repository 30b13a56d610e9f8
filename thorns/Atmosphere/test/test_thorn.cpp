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
  const remnant::ThornSpec t = spec();
  EXPECT_EQ(t.name, "Atmosphere");
  ASSERT_EQ(t.provides.size(), 1u);
  EXPECT_EQ(t.provides[0], "atmosphere");
  ASSERT_EQ(t.schedule.size(), 1u);
  EXPECT_EQ(t.schedule[0].name, "Atmosphere_Startup");
  EXPECT_EQ(t.schedule[0].in, "startup");
  ASSERT_EQ(t.schedule[0].after.size(), 1u);
  EXPECT_EQ(t.schedule[0].after[0].name, "EOS_Startup");
  remnant::test::RecordingRegistrar r;
  remnant_register_thorn_Atmosphere(r);
  EXPECT_EQ(r.fns.count("Atmosphere_Startup"), 1u);
}

TEST(AtmosphereThorn, StartupPublishesTheAtmosphere) {
  remnant::Parameters params;
  for (auto p : spec().parameters) params.declare(p);
  remnant::VariableRegistry vars;
  remnant::Context ctx(params, vars, MPI_COMM_WORLD);
  remnant::test::RecordingRegistrar r;
  remnant_register_thorn_Atmosphere(r);
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
