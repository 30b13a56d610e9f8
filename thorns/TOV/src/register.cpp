// TOV_Initial: solve the star, then write prim (interior) and the metric (everywhere: no ghost sync
// needed, and ghosts across the origin or an axis get the mirror point's values).
#include <cmath>
#include <cstdio>
#include <numbers>

#include "TOV/tov_solver.hpp"
#include "check_parameters.hpp"
#include "slice_from_parameters.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/context.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/registrar.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::tov {
namespace {

void initial(Context& ctx) {
  const auto slice = slice_from_parameters(ctx);
  const TovStar star(*slice, ctx.param<double>("TOV", "rho_central"),
                     static_cast<int>(ctx.param<std::int64_t>("TOV", "samples")));
  char line[256];
  std::snprintf(line, sizeof line,
                "TOV: M = %.6f, M0 = %.6f, R = %.5f (areal), %.5f (isotropic), rho_c = %.6e, Hc = %.6f",
                star.gravitational_mass(), star.rest_mass(), star.areal_radius(), star.isotropic_radius(),
                ctx.param<double>("TOV", "rho_central"), star.central_log_enthalpy());
  ctx.info(line);
  const bool perturb = ctx.param<std::string>("TOV", "perturbation") == "radial_velocity";
  const double amp = ctx.param<double>("TOV", "perturbation_amplitude");
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    const vars::Spacetime::metric metric(ctx, *b);
    const CoordinateSystem cs = b->coordinates;
    auto radius = [&](const Point3& x) {
      const Point3 X = coords::to_cartesian(cs, x);
      return std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
    };
    // Metric everywhere (ghosts included).
    for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
      for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
        for (int i = -b->ng[0]; i < b->n[0] + b->ng[0]; ++i) {
          const TovPoint p = star.at(radius(cell_point(*b, i, j, k)));
          metric.psi(i, j, k) = p.psi;
          metric.alpha(i, j, k) = p.alpha;
          for (int c = 0; c < 3; ++c) metric.beta(c, i, j, k) = 0.0;
        }
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 x = cell_point(*b, i, j, k);
      const double r = radius(x);
      const TovPoint p = star.at(r);
      Point3 v{0, 0, 0};
      if (perturb && p.inside && r > 0) {
        const Point3 X = coords::to_cartesian(cs, x);
        const double s = amp * std::sin(std::numbers::pi * r / star.isotropic_radius()) / r;
        v = coords::vector_from_cartesian(cs, x, {s * X[0], s * X[1], s * X[2]});
      }
      prim.rho(i, j, k) = p.rho;
      for (int c = 0; c < 3; ++c) prim.vel(c, i, j, k) = v[c];
      prim.eps(i, j, k) = p.eps;
      prim.press(i, j, k) = p.press;
      prim.temperature(i, j, k) = 0.0;  // T follows from eps in HydroBase_InitialCons
      prim.Ye(i, j, k) = p.ye;
      prim.W(i, j, k) = 1.0;
      prim.cs2(i, j, k) = 0.0;
    });
  }
}

}  // namespace
}  // namespace remnant::tov

REMNANT_REGISTER_THORN(TOV) {
  reg.function("TOV_CheckParameters", remnant::tov::check_parameters);
  reg.function("TOV_Initial", remnant::tov::initial);
}
