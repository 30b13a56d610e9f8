#include "shock_tube.hpp"

#include "EOS/eos.hpp"
#include "GRMHD/grid_access.hpp"

namespace remnant::grmhd {

namespace {
ShockTubeState state_from(const std::vector<double>& p) { return {p[0], p[4], {p[1], p[2], p[3]}}; }
}  // namespace

void shock_tube_initial_data(Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto* ideal = std::get_if<eos::IdealGas<>>(&eos.variant());
  if (!ideal) throw RunError("GRMHD::initial_data = shock_tube needs EOS::type = ideal_gas");
  const double gm1 = ideal->gamma() - 1.0;
  const ShockTubeState left = state_from(ctx.param<std::vector<double>>("GRMHD", "shock_left"));
  const ShockTubeState right = state_from(ctx.param<std::vector<double>>("GRMHD", "shock_right"));
  const double x0 = ctx.param<double>("GRMHD", "shock_position");
  const double ye = ctx.param<double>("GRMHD", "initial_ye");
  const Groups g = Groups::of(ctx);
  for (Block* b : ctx.grid().local_blocks()) {
    Field prim[kNumPrim];
    for (int c = 0; c < kNumPrim; ++c) prim[c] = b->field(g.prim, c);
    for_interior(*b, [&](int i, int j, int k) {
      const ShockTubeState& s = b->x(0, i) < x0 ? left : right;
      prim[kRho](i, j, k) = s.rho;
      for (int c = 0; c < 3; ++c) prim[kVel1 + c](i, j, k) = s.v[c];
      prim[kPress](i, j, k) = s.press;
      prim[kEps](i, j, k) = s.press / (gm1 * s.rho);
      prim[kYe](i, j, k) = ye;
      prim[kTemp](i, j, k) = 0;
    });
  }
}

}  // namespace remnant::grmhd
