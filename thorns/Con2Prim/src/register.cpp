// Binds Con2Prim_Startup: publishes the recovery settings as service "con2prim". The grid sweep
// comes with the GRMHD thorn, which calls recover() per cell with these settings and the services
// "eos" and "atmosphere".
#include <cstdio>

#include <remnant/context.hpp>
#include <remnant/registrar.hpp>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/settings.hpp"
#include "EOS/units.hpp"

namespace {

using remnant::Context;
namespace c2p = remnant::con2prim;

c2p::Settings settings_from(const Context& ctx) {
  c2p::Settings s;
  auto real = [&](const char* n) { return ctx.param<double>("Con2Prim", n); };
  auto word = [&](const char* n) { return ctx.param<std::string>("Con2Prim", n); };
  c2p::parse_method(word("method"), s.method);
  s.tolerance = real("tolerance");
  s.max_iterations = int(ctx.param<std::int64_t>("Con2Prim", "max_iterations"));
  s.eps_to_T = word("eps_to_T") == "brent" ? remnant::eos::InversionMethod::brent : remnant::eos::InversionMethod::exact;
  s.secant_polish = ctx.param<bool>("Con2Prim", "secant_polish");
  s.accuracy = real("accuracy");
  s.policy.W_max = real("W_max");
  s.policy.rho_W_limit = real("W_max_rho_limit");  // code units, like every density parameter
  return s;
}

}  // namespace

REMNANT_REGISTER_THORN(Con2Prim) {
  reg.function("Con2Prim_Startup", [](Context& ctx) {
    auto s = std::make_shared<c2p::Settings>(settings_from(ctx));
    char line[320];
    std::snprintf(line, sizeof line,
                  "Con2Prim: method %s, tolerance %g, max_iterations %d, eps_to_T %s, W_max %g at rho <= %g "
                  "(code units, %g g/cm^3)",
                  c2p::to_string(s->method), s->tolerance, s->max_iterations,
                  s->eps_to_T == remnant::eos::InversionMethod::brent ? "brent" : "exact", s->policy.W_max,
                  s->policy.rho_W_limit, s->policy.rho_W_limit / remnant::units::rho_cgs_to_code);
    ctx.info(line);
    if (ctx.has_service("atmosphere")) {
      const auto& atm = ctx.service<remnant::atmosphere::Atmosphere>("atmosphere");
      const std::string why = c2p::rule10_never_applies(s->policy, atm.rho_thr);
      if (!why.empty()) ctx.warn(why);
    }
    ctx.publish<c2p::Settings>("con2prim", std::move(s));
  });
}
