// Binds Atmosphere_Startup: builds the atmosphere state from the EOS service and the parameters and
// publishes it as service "atmosphere" (type remnant::atmosphere::Atmosphere).
#include <remnant/context.hpp>
#include <remnant/registrar.hpp>

#include "Atmosphere/make_atmosphere.hpp"

namespace {

using remnant::Context;
namespace atmo = remnant::atmosphere;

atmo::AtmosphereConfig config_from(const Context& ctx) {
  auto real = [&](const char* n) { return ctx.param<double>("Atmosphere", n); };
  atmo::AtmosphereConfig c;
  c.rho_thr = real("rho_thr");
  c.xi = real("xi");
  c.poly_K = real("poly_K");
  c.poly_gamma = real("poly_gamma");
  c.ye_analytic = real("ye_analytic");
  c.sigma_max = real("sigma_max");
  return c;
}

}  // namespace

REMNANT_REGISTER_THORN(Atmosphere) {
  reg.function("Atmosphere_Startup", [](Context& ctx) {
    const auto& eos = ctx.service<remnant::eos::EOS>("eos");
    try {
      auto a = std::make_shared<atmo::Atmosphere>(atmo::make_atmosphere(eos, config_from(ctx)));
      ctx.info("Atmosphere: " + atmo::describe(*a));
      if (a->ye_source == atmo::YeSource::beta_nearest_end || a->ye_source == atmo::YeSource::table_without_mu)
        ctx.warn("Atmosphere: Ye_atm is not in beta equilibrium: " + atmo::describe(*a));
      if (const auto* t = eos.tabulated(); t && a->rho < t->bounds().rho_min)
        ctx.warn("Atmosphere: rho_atm is below the table's rho_min; the table is evaluated at its edge");
      ctx.publish<atmo::Atmosphere>("atmosphere", std::move(a));
    } catch (const std::exception& err) {
      throw remnant::RunError(std::string("Atmosphere_Startup: ") + err.what());
    }
  });
}
