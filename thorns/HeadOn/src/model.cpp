#include "model.hpp"

#include <cstdio>

#include "EOS/eos.hpp"
#include "TOV/table_slice.hpp"

namespace remnant::headon {

std::unique_ptr<tov::ColdSlice> slice_from_parameters(const Context& ctx) {
  if (ctx.param<std::string>("HeadOn", "eos_slice") == "polytrope")
    return tov::polytrope_slice(ctx.param<double>("HeadOn", "poly_K"), ctx.param<double>("HeadOn", "poly_gamma"),
                                ctx.param<double>("HeadOn", "ye"));
  const auto* table = ctx.service<eos::EOS>("eos").tabulated();
  if (!table) throw RunError("HeadOn::eos_slice = tabulated_beta needs EOS::type = tabulated");
  return tov::cold_beta_slice(*table);
}

const Model& model(Context& ctx) {
  if (ctx.has_service("HeadOn::model")) return ctx.service<Model>("HeadOn::model");
  auto m = std::make_shared<Model>();
  m->slice = slice_from_parameters(ctx);
  m->star = std::make_unique<tov::TovStar>(*m->slice, ctx.param<double>("HeadOn", "rho_central"),
                                           static_cast<int>(ctx.param<std::int64_t>("HeadOn", "samples")));
  m->binary = std::make_unique<Binary>(*m->star, ctx.param<double>("HeadOn", "separation"),
                                       ctx.param<double>("HeadOn", "infall_velocity"));
  char line[320];
  std::snprintf(line, sizeof line,
                "HeadOn: each star M = %.6f, M0 = %.6f, R = %.5f (areal), %.5f (isotropic), rho_c = %.6e; "
                "centres z = +-%.5f (d = %.5f = %.3f isotropic radii)",
                m->star->gravitational_mass(), m->star->rest_mass(), m->star->areal_radius(),
                m->star->isotropic_radius(), ctx.param<double>("HeadOn", "rho_central"),
                0.5 * m->binary->separation(), m->binary->separation(),
                m->binary->separation() / m->star->isotropic_radius());
  ctx.info(line);
  ctx.publish("HeadOn::model", m);
  return *m;
}

}  // namespace remnant::headon
