// The thorn binding: thorn.yaml parses, and EOS_Startup builds and publishes the EOS service.
// Needs the framework (remnant_flesh); built only by the project's CMake.
#include <fstream>
#include <map>
#include <sstream>

#include <remnant/context.hpp>
#include <remnant/registrar.hpp>
#include <remnant_test/thorn_fixture.hpp>
#include <remnant/thorn_spec.hpp>

#include "EOS/eos.hpp"
#include "eos_test_util.hpp"

void remnant_register_thorn_EOS(remnant::ThornRegistrar&);

namespace {


remnant::ThornSpec spec() { return remnant::test::thorn_spec_from_source(REMNANT_SOURCE_DIR, "EOS"); }

}  // namespace

TEST(EOSThorn, ThornYamlParsesAndDeclaresStartup) {
  remnant::test::expect_startup_provider(spec(), "EOS", "eos", "", remnant_register_thorn_EOS);
}

TEST(EOSThorn, StartupPublishesTheEos) {
  const std::string table = eos_test::shared_eos("SFHo_reduced_39r_39t_20y_compose.h5");
  REQUIRE_TABLE(table);
  remnant::test::ThornContext thorn(spec(), remnant_register_thorn_EOS);
  auto& [params, vars, ctx, r] = thorn;

  r.fns.at("EOS_Startup")(ctx);  // defaults: an ideal gas
  EXPECT_FALSE(ctx.service<remnant::eos::EOS>("eos").is_tabulated());

  params.set("EOS", "type", std::string("tabulated"), {});
  params.set("EOS", "table_file", table, {});
  r.fns.at("EOS_Startup")(ctx);
  const auto& e = ctx.service<remnant::eos::EOS>("eos");
  ASSERT_TRUE(e.is_tabulated());
  EXPECT_EQ(e.tabulated()->table().lrho.n, 39);
  // Its node (1.377e-4, T_min, Ye 0.0721) has a thermal-index jump (158 vs 5.0): a warning, which
  // EOS::table_thermal_index_jump = 200 silences.
  EXPECT_NE(e.tabulated()->table().report.find("thermal_index"), nullptr);
  params.set("EOS", "table_thermal_index_jump", 200.0, {});
  r.fns.at("EOS_Startup")(ctx);
  EXPECT_EQ(ctx.service<remnant::eos::EOS>("eos").tabulated()->table().report.find("thermal_index"), nullptr);
  // EOS::table_repair_thermal_index = true replaces that node's pressure instead (a logged warning).
  params.set("EOS", "table_thermal_index_jump", 10.0, {});
  params.set("EOS", "table_repair_thermal_index", true, {});
  r.fns.at("EOS_Startup")(ctx);
  EXPECT_EQ(ctx.service<remnant::eos::EOS>("eos").tabulated()->table().report.find("thermal_index"), nullptr);
  EXPECT_NE(ctx.service<remnant::eos::EOS>("eos").tabulated()->table().report.find("thermal_index_repair"), nullptr);
  params.set("EOS", "table_repair_thermal_index", false, {});

  params.set("EOS", "table_file", std::string("/nonexistent/table.h5"), {});
  try {
    r.fns.at("EOS_Startup")(ctx);
    ADD_FAILURE() << "no error for a missing table";
  } catch (const remnant::RunError& err) {
    EXPECT_NE(std::string(err.what()).find("/nonexistent/table.h5"), std::string::npos);
  }
}
