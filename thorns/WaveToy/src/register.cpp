// WaveToy: the scalar wave equation on the block grid, second order in space.
#include <cmath>

#include "exact_solution.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "remnant/vars/WaveToy.hpp"

namespace remnant::wavetoy {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

WaveSetup setup_from(const Context& ctx) {
  WaveSetup s;
  s.kind = wave_kind(ctx.param<std::string>("WaveToy", "initial_data"));
  s.amplitude = ctx.param<double>("WaveToy", "amplitude");
  const auto& n = ctx.param<std::vector<double>>("WaveToy", "wave_numbers");
  for (int d = 0; d < 3; ++d) s.k[d] = kTwoPi * n[d];
  s.speed = ctx.param<double>("WaveToy", "speed");
  s.width = ctx.param<double>("WaveToy", "gaussian_width");
  const auto& c = ctx.param<std::vector<double>>("WaveToy", "gaussian_center");
  for (int d = 0; d < 3; ++d) s.center[d] = c[d];
  return s;
}

void initial(Context& ctx) {
  const WaveSetup s = setup_from(ctx);
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::WaveToy::wave wave(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const WaveState w = exact_solution(s, ctx.time(), b->x(0, i), b->x(1, j), b->x(2, k));
      wave.u(i, j, k) = w.u;
      wave.rho(i, j, k) = w.rho;
    });
  }
}

void rhs(Context& ctx) {
  const double c2 = std::pow(ctx.param<double>("WaveToy", "speed"), 2);
  using Wave = vars::WaveToy::wave;
  using WaveRhs = vars::WaveToy::wave_rhs;
  for (Block* b : ctx.grid().local_blocks()) {
    const Wave wave(ctx, *b);
    const WaveRhs wave_rhs(ctx, *b);
    const Field u = wave.field(Wave::idx::u), rho = wave.field(Wave::idx::rho);
    const Field du = wave_rhs.field(WaveRhs::idx::u), drho = wave_rhs.field(WaveRhs::idx::rho);
    // Unused directions (no ghosts) get zero weight, so one loop serves 1D, 2D and 3D.
    const double wx = b->ng[0] > 0 ? c2 / (b->dx[0] * b->dx[0]) : 0.0;
    const double wy = b->ng[1] > 0 ? c2 / (b->dx[1] * b->dx[1]) : 0.0;
    const double wz = b->ng[2] > 0 ? c2 / (b->dx[2] * b->dx[2]) : 0.0;
    const std::ptrdiff_t sy = b->ng[1] > 0 ? u.sj : 0, sz = b->ng[2] > 0 ? u.sk : 0;
    for (int k = 0; k < b->n[2]; ++k)
      for (int j = 0; j < b->n[1]; ++j) {
        const double* up = &u(0, j, k);
        const double* rp = &rho(0, j, k);
        double* dup = &du(0, j, k);
        double* drp = &drho(0, j, k);
        for (int i = 0; i < b->n[0]; ++i) {
          const double uc = up[i];
          dup[i] = rp[i];
          drp[i] = wx * (up[i + 1] - 2 * uc + up[i - 1]) + wy * (up[i + sy] - 2 * uc + up[i - sy]) +
                   wz * (up[i + sz] - 2 * uc + up[i - sz]);
        }
      }
  }
}

void error(Context& ctx) {
  const WaveSetup s = setup_from(ctx);
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::WaveToy::wave wave(ctx, *b);
    const vars::WaveToy::wave_error err(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      err.u_err(i, j, k) = wave.u(i, j, k) - exact_solution(s, ctx.time(), b->x(0, i), b->x(1, j), b->x(2, k)).u;
    });
  }
}

// CFL: c dt sqrt(sum 1/dx^2) <= cfl.
double inverse_dt(Context& ctx) {
  const double c = ctx.param<double>("WaveToy", "speed");
  double inv = 0;
  for (Block* b : ctx.grid().local_blocks()) {
    double s = 0;
    for (int d = 0; d < 3; ++d)
      if (b->ng[d] > 0) s += 1.0 / (b->dx[d] * b->dx[d]);
    inv = std::max(inv, c * std::sqrt(s));
  }
  return inv;
}

}  // namespace
}  // namespace remnant::wavetoy

REMNANT_REGISTER_THORN(WaveToy) {
  using namespace remnant::wavetoy;
  reg.function("WaveToy_Initial", initial);
  reg.function("WaveToy_RHS", rhs);
  reg.function("WaveToy_Error", error);
  reg.inverse_dt_limit(inverse_dt);
}
