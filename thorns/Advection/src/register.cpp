// Advection: u_t + div(u v) = 0 on the Grid's exact geometry, with refluxing.
#include <algorithm>
#include <cmath>
#include <vector>

#include "exact_solution.hpp"
#include "fluxes.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"

namespace remnant::advection {
namespace {

Setup setup_from(const Context& ctx) {
  Setup s;
  s.coords = ctx.grid().coordinates();
  const std::string& kind = ctx.param<std::string>("Advection", "velocity");
  s.kind = kind == "rotation" ? VelocityKind::rotation : kind == "radial" ? VelocityKind::radial : VelocityKind::cartesian;
  const auto& v = ctx.param<std::vector<double>>("Advection", "velocity_vector");
  const auto& c = ctx.param<std::vector<double>>("Advection", "profile_center");
  for (std::size_t d = 0; d < 3; ++d) {
    s.velocity[d] = v[d];
    s.centre[d] = c[d];
  }
  s.omega = ctx.param<double>("Advection", "omega");
  s.radial_speed = ctx.param<double>("Advection", "radial_speed");
  s.width = ctx.param<double>("Advection", "profile_width");
  s.amplitude = ctx.param<double>("Advection", "amplitude");
  s.background = ctx.param<double>("Advection", "background");
  return s;
}

Point3 centroid(const Block& b, int i, int j, int k) { return {b.centroid(0, i), b.centroid(1, j), b.centroid(2, k)}; }

void register_criterion(Context& ctx) {
  const double radius = ctx.param<double>("Advection", "refine_radius");
  if (radius <= 0) return;
  Context* c = &ctx;
  ctx.grid().add_refinement_criterion("Advection::moving_bump", [c, radius](Block& b) {
    const Setup s = setup_from(*c);
    const Point3 centre = centre_at(s, c->time());
    for (int k = 0; k < b.n[2]; ++k)
      for (int j = 0; j < b.n[1]; ++j)
        for (int i = 0; i < b.n[0]; ++i) {
          const Point3 x = centroid(b, i, j, k);
          double dist;
          if (s.kind == VelocityKind::radial) {
            dist = std::abs(x[0] - centre[0]);
          } else {
            const Point3 X = coords::to_cartesian(s.coords, x);
            dist = std::hypot(X[0] - centre[0], X[1] - centre[1], X[2] - centre[2]);
          }
          if (dist < radius) return 1;
        }
    return -1;
  });
}

void initial(Context& ctx) {
  const Setup s = setup_from(ctx);
  const int u = ctx.var("Advection::u");
  for (Block* b : ctx.grid().local_blocks()) {
    Field f = b->field(u, 0);
    for_interior(*b, [&](int i, int j, int k) { f(i, j, k) = exact(s, ctx.time(), centroid(*b, i, j, k)); });
  }
}

void rhs(Context& ctx) {
  const Setup s = setup_from(ctx);
  const int u = ctx.var("Advection::u"), u_rhs = ctx.var("Advection::u_rhs");
  const int flux_groups[3] = {ctx.var("Advection::flux_x"), ctx.var("Advection::flux_y"), ctx.var("Advection::flux_z")};
  const int dim = ctx.grid().dimension();
  for (Block* b : ctx.grid().local_blocks())
    for (int d = 0; d < dim; ++d) face_fluxes(s, *b, b->field(u, 0), b->field(flux_groups[d], 0), d);
  // Unused directions carry no flux (and must not hold stale values: debug mode checks).
  for (Block* b : ctx.grid().local_blocks())
    for (int d = dim; d < 3; ++d) std::fill(b->data(flux_groups[d]), b->data(flux_groups[d]) + b->size(flux_groups[d]), 0.0);
  ctx.grid().correct_fluxes(std::span<const int>(flux_groups, static_cast<std::size_t>(dim)));
  for (Block* b : ctx.grid().local_blocks()) {
    const Field f[3] = {b->field(flux_groups[0], 0), b->field(flux_groups[1], 0), b->field(flux_groups[2], 0)};
    const Field* fp[3] = {&f[0], &f[1], &f[2]};
    flux_divergence(*b, fp, dim, b->field(u_rhs, 0));
  }
}

void error(Context& ctx) {
  const Setup s = setup_from(ctx);
  const int u = ctx.var("Advection::u"), err = ctx.var("Advection::u_error");
  for (Block* b : ctx.grid().local_blocks()) {
    Field f = b->field(u, 0), e = b->field(err, 0);
    for_interior(*b, [&](int i, int j, int k) { e(i, j, k) = f(i, j, k) - exact(s, ctx.time(), centroid(*b, i, j, k)); });
  }
}

double max_inverse_dt(Context& ctx) {
  const Setup s = setup_from(ctx);
  double inv = 0;
  for (Block* b : ctx.grid().local_blocks()) inv = std::max(inv, inverse_dt(s, *b, ctx.grid().dimension()));
  return inv;
}

}  // namespace
}  // namespace remnant::advection

REMNANT_REGISTER_THORN(Advection) {
  using namespace remnant::advection;
  reg.function("Advection_RegisterCriterion", register_criterion);
  reg.function("Advection_Initial", initial);
  reg.function("Advection_RHS", rhs);
  reg.function("Advection_Error", error);
  reg.inverse_dt_limit(max_inverse_dt);
}
