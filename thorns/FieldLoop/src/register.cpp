// FieldLoop: constrained-transport advection of a magnetic field loop through MoL.
#include <algorithm>
#include <cmath>

#include "constrained_transport.hpp"
#include "remnant/context.hpp"
#include "remnant/error.hpp"
#include "remnant/registrar.hpp"

namespace remnant::field_loop {
namespace {

Loop loop_from(const Context& ctx) {
  Loop l;
  const auto& v = ctx.param<std::vector<double>>("FieldLoop", "velocity");
  const auto& c = ctx.param<std::vector<double>>("FieldLoop", "loop_center");
  l.velocity = {v[0], v[1]};
  l.centre = {c[0], c[1]};
  l.radius = ctx.param<double>("FieldLoop", "loop_radius");
  l.amplitude = ctx.param<double>("FieldLoop", "amplitude");
  const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& hi = ctx.param<std::vector<double>>("Grid", "xmax");
  l.period = {hi[0] - lo[0], hi[1] - lo[1]};
  return l;
}

void check_grid(Context& ctx) {
  if (ctx.grid().coordinates() != CoordinateSystem::cartesian || ctx.grid().dimension() != 2)
    throw InputError(ctx.params().origin("Grid", "dimension"),
                     "FieldLoop runs on 2D Cartesian grids (Grid::coordinates = cartesian, Grid::dimension = 2)");
}

void register_criterion(Context& ctx) {
  const double radius = ctx.param<double>("FieldLoop", "refine_radius");
  if (radius <= 0) return;
  Context* c = &ctx;
  ctx.grid().add_refinement_criterion("FieldLoop::moving_loop", [c, radius](Block& b) {
    const Loop l = loop_from(*c);
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i)
        if (distance_to_centre(l, c->time(), b.x(0, i), b.x(1, j)) < radius) return 1;
    return -1;
  });
}

void initial(Context& ctx) {
  const Loop l = loop_from(ctx);
  const int bx = ctx.var("FieldLoop::Bx"), by = ctx.var("FieldLoop::By");
  for (Block* b : ctx.grid().local_blocks()) set_initial(l, ctx.time(), *b, b->field(bx, 0), b->field(by, 0));
}

void rhs(Context& ctx) {
  const Loop l = loop_from(ctx);
  const int bx = ctx.var("FieldLoop::Bx"), by = ctx.var("FieldLoop::By"), ez = ctx.var("FieldLoop::Ez");
  const int bx_rhs = ctx.var("FieldLoop::Bx_rhs"), by_rhs = ctx.var("FieldLoop::By_rhs");
  for (Block* b : ctx.grid().local_blocks()) corner_emf(l, *b, b->field(bx, 0), b->field(by, 0), b->field(ez, 0));
  // Coarse copies of the edges of finer blocks take the fine EMFs: the fluxes through a
  // coarse/fine interface stay the sum of the fine ones.
  const int edges[1] = {ez};
  ctx.grid().correct_edges(edges);
  for (Block* b : ctx.grid().local_blocks()) face_rhs(*b, b->field(ez, 0), b->field(bx_rhs, 0), b->field(by_rhs, 0));
}

void analysis(Context& ctx) {
  const int bx = ctx.var("FieldLoop::Bx"), by = ctx.var("FieldLoop::By");
  const int b2 = ctx.var("FieldLoop::b2"), div = ctx.var("FieldLoop::divB");
  for (Block* b : ctx.grid().local_blocks()) analyse(*b, b->field(bx, 0), b->field(by, 0), b->field(b2, 0), b->field(div, 0));
}

double max_inverse_dt(Context& ctx) {
  const Loop l = loop_from(ctx);
  double inv = 0;
  for (Block* b : ctx.grid().local_blocks())
    inv = std::max(inv, std::abs(l.velocity[0]) / b->dx[0] + std::abs(l.velocity[1]) / b->dx[1]);
  return inv;
}

}  // namespace
}  // namespace remnant::field_loop

REMNANT_REGISTER_THORN(FieldLoop) {
  using namespace remnant::field_loop;
  reg.function("FieldLoop_CheckGrid", check_grid);
  reg.function("FieldLoop_RegisterCriterion", register_criterion);
  reg.function("FieldLoop_Initial", initial);
  reg.function("FieldLoop_RHS", rhs);
  reg.function("FieldLoop_Analysis", analysis);
  reg.inverse_dt_limit(max_inverse_dt);
}
