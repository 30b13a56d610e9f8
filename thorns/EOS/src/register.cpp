// Binds EOS_Startup: builds the EOS from the parameters and publishes it as service "eos"
// (type remnant::eos::EOS). Table check warnings go to the log.
#include <remnant/context.hpp>
#include <remnant/registrar.hpp>

#include "EOS/eos.hpp"

namespace {

using remnant::Context;
namespace eos = remnant::eos;

eos::EosConfig config_from(const Context& ctx) {
  eos::EosConfig c;
  auto real = [&](const char* n) { return ctx.param<double>("EOS", n); };
  auto word = [&](const char* n) { return ctx.param<std::string>("EOS", n); };
  c.type = word("type");
  c.gamma = real("gamma");
  c.baryon_mass_MeV = real("baryon_mass");
  c.poly_K = real("poly_K");
  c.poly_gammas = ctx.param<std::vector<double>>("EOS", "poly_gammas");
  c.poly_rho_bounds = ctx.param<std::vector<double>>("EOS", "poly_rho_bounds");
  c.gamma_th = real("gamma_th");
  c.rho_min = real("rho_min");
  c.rho_max = real("rho_max");
  c.T_max = real("T_max");
  c.table_file = word("table_file");
  const std::string f = word("table_format");
  c.read.format = f == "stellarcollapse" ? eos::TableFormat::stellarcollapse
                  : f == "compose_ascii" ? eos::TableFormat::compose_ascii
                  : f == "compose_hdf5"  ? eos::TableFormat::compose_hdf5
                                         : eos::TableFormat::automatic;
  const std::string cs2 = word("table_cs2");
  c.read.sc_cs2 = cs2 == "relativistic" ? eos::Cs2Convention::relativistic
                  : cs2 == "newtonian"  ? eos::Cs2Convention::newtonian
                                        : eos::Cs2Convention::from_file;
  c.read.compose_mu_e =
      word("compose_mu_e") == "mu_l" ? eos::ComposeElectronMu::mu_l : eos::ComposeElectronMu::mu_l_minus_mu_q;
  c.read.build.clamp_cs2 = ctx.param<bool>("EOS", "clamp_cs2");
  c.read.build.max_inconsistent_fraction = ctx.param<double>("EOS", "table_max_inconsistent_fraction");
  c.read.build.thermal_index_max = ctx.param<double>("EOS", "table_thermal_index_max");
  c.read.build.thermal_index_jump = ctx.param<double>("EOS", "table_thermal_index_jump");
  c.read.build.repair_thermal_index = ctx.param<bool>("EOS", "table_repair_thermal_index");
  return c;
}

}  // namespace

REMNANT_REGISTER_THORN(EOS) {
  reg.function("EOS_Startup", [](Context& ctx) {
    try {
      auto e = std::make_shared<eos::EOS>(eos::make_eos(config_from(ctx)));
      ctx.info("EOS: " + e->describe());
      if (const auto* t = e->tabulated())
        for (const auto& issue : t->table().report.issues)
          if (issue.level == eos::CheckIssue::Level::warning) ctx.warn(issue.str());
      ctx.publish<eos::EOS>("eos", std::move(e));
    } catch (const eos::EosError& err) {
      throw remnant::RunError(std::string("EOS_Startup: ") + err.what());
    }
  });
}
