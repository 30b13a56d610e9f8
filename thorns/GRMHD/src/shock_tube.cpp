#include "shock_tube.hpp"

#include <cmath>

#include "EOS/eos.hpp"
#include "groups.hpp"

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
  for (Block* b : ctx.grid().local_blocks()) {
    const Prim prim(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const ShockTubeState& s = b->x(0, i) < x0 ? left : right;
      prim.rho(i, j, k) = s.rho;
      for (int c = 0; c < 3; ++c) prim.vel(c, i, j, k) = s.v[c];
      prim.press(i, j, k) = s.press;
      prim.eps(i, j, k) = s.press / (gm1 * s.rho);
      prim.Ye(i, j, k) = ye;
      prim.temperature(i, j, k) = 0;
      // Flat space: W from the coordinate velocity; cs2 is recomputed by HydroBase_InitialCons.
      prim.W(i, j, k) = 1.0 / std::sqrt(1.0 - (s.v[0] * s.v[0] + s.v[1] * s.v[1] + s.v[2] * s.v[2]));
      prim.cs2(i, j, k) = 0;
    });
  }
}

}  // namespace remnant::grmhd
