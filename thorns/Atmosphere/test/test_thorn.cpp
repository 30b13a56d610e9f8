// The thorn binding: thorn.yaml parses; Atmosphere_Startup reads the EOS service and publishes
// service "atmosphere".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <remnant/context.hpp>
#include <remnant/registrar.hpp>
#include <remnant/thorn_spec.hpp>

#include "Atmosphere/make_atmosphere.hpp"

void remnant_register_thorn_Atmosphere(remnant::ThornRegistrar&);

namespace {

// Mirrors remnant::ThornRegistrar: update when the framework adds a hook.
struct Recorder : remnant::ThornRegistrar {
  std::map<std::string, remnant::ScheduledFunction> fns;
  void function(const std::string& n, remnant::ScheduledFunction f) override { fns[n] = std::move(f); }
  void predicate(const std::string&, remnant::Predicate) override {}
  void inverse_dt_limit(std::function<double(remnant::Context&)>) override {}
  void termination_check(std::function<std::string(remnant::Context&)>) override {}
  void progress_fraction(std::function<double(remnant::Context&)>) override {}
  void grid_factory(std::function<std::unique_ptr<remnant::GridDriver>(const remnant::GridSetup&)>) override {}
};

remnant::ThornSpec spec() {
  const std::string path = std::string(REMNANT_SOURCE_DIR) + "/thorns/Atmosphere/thorn.yaml";
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return remnant::parse_thorn_spec(s.str(), path);
}

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
  Recorder r;
  remnant_register_thorn_Atmosphere(r);
  EXPECT_EQ(r.fns.count("Atmosphere_Startup"), 1u);
}

TEST(AtmosphereThorn, StartupPublishesTheAtmosphere) {
  remnant::Parameters params;
  for (auto p : spec().parameters) params.declare(p);
  remnant::VariableRegistry vars;
  remnant::Context ctx(params, vars, MPI_COMM_WORLD);
  Recorder r;
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
