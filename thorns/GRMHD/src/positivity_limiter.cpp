#include "positivity_limiter.hpp"

#include <cmath>
#include <string>

#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {

long limit_block_mass_fluxes(const Groups& g, double dt, double epsilon, Block& b) {
  int used_dims = 0;
  for (int d = 0; d < 3; ++d) used_dims += direction_used(b, d) ? 1 : 0;
  if (used_dims == 0 || !(dt > 0)) return 0;
  const Field rho = b.field(g.prim, Prim::idx::rho), w = b.field(g.prim, Prim::idx::W),
              ye = b.field(g.prim, Prim::idx::Ye), psi = b.field(g.metric, Metric::idx::psi),
              alpha = b.field(g.metric, Metric::idx::alpha);
  const double split = 2.0 * used_dims * dt;
  long limited = 0;
  for (int d = 0; d < 3; ++d) {
    if (!direction_used(b, d)) continue;
    const Field vel = b.field(g.prim, Prim::idx::vel + d), beta = b.field(g.metric, Metric::idx::beta + d);
    Field fd = b.field(g.flux[d], kD), fy = b.field(g.flux[d], kDYe);
    const double* ff = b.face_factors(d);
    const double* vw = b.volume_weights(d);
    const std::ptrdiff_t sc = d == 0 ? 1 : d == 1 ? rho.sj : rho.sk;  // cell stride along d
    const std::ptrdiff_t sf = d == 0 ? 1 : d == 1 ? fd.sj : fd.sk;    // face stride along d
    const int ext[3] = {d == 0 ? 1 : b.n[0], d == 1 ? 1 : b.n[1], d == 2 ? 1 : b.n[2]};
    for (int k = 0; k < ext[2]; ++k)
      for (int j = 0; j < ext[1]; ++j)
        for (int i = 0; i < ext[0]; ++i) {
          const std::ptrdiff_t oc = i + j * rho.sj + k * rho.sk, of = i + j * fd.sj + k * fd.sk;
          // Cell m of face f is f - 1, cell p is f: walk the line keeping the previous cell.
          auto cell = [&](int m, double& dens, double& vt, double& y) {
            const std::ptrdiff_t o = oc + m * sc;
            const double p2 = psi.origin[o] * psi.origin[o];
            dens = p2 * p2 * p2 * rho.origin[o] * w.origin[o];
            vt = alpha.origin[o] * vel.origin[o] - beta.origin[o];
            y = ye.origin[o];
          };
          double dm, vm, ym;
          cell(-1, dm, vm, ym);
          for (int f = 0; f <= b.n[d]; ++f) {
            double dp, vp, yp;
            cell(f, dp, vp, yp);
            const double area = ff[f];
            const double cm = area > 0 && vw[f - 1] > 0 ? split * area / vw[f - 1] : 0.0;
            const double cp = area > 0 && vw[f] > 0 ? split * area / vw[f] : 0.0;
            double& fhd = fd.origin[of + f * sf];
            const double a = std::max(std::abs(vm), std::abs(vp));
            const double fld = lax_friedrichs_flux(dm, dp, vm, vp, a);
            const double theta = positivity_theta(dm, dp, cm, cp, fhd, fld, epsilon);
            if (theta < 1.0) {
              double& fhy = fy.origin[of + f * sf];
              const double fly = lax_friedrichs_flux(dm * ym, dp * yp, vm, vp, a);
              fhd = theta * fhd + (1.0 - theta) * fld;
              fhy = theta * fhy + (1.0 - theta) * fly;
              ++limited;
            }
            dm = dp, vm = vp, ym = yp;
          }
        }
  }
  return limited;
}

void apply_positivity_limiter(Context& ctx, const Groups& g) {
  if (ctx.param<std::string>("GRMHD", "positivity_limiter") == "none") return;
  const double epsilon = ctx.param<double>("GRMHD", "positivity_epsilon");
  for (Block* b : ctx.grid().local_blocks()) limit_block_mass_fluxes(g, ctx.dt(), epsilon, *b);
}

void check_positivity_limiter(Context& ctx) {
  if (ctx.param<std::string>("GRMHD", "positivity_limiter") == "none" || ctx.rank() != 0) return;
  const double cfl = ctx.param<double>("MoL", "cfl"), bound = 0.5 / ctx.grid().dimension();
  if (ctx.param<double>("MoL", "dt") <= 0 && cfl > bound)
    ctx.warn("GRMHD::positivity_limiter = lax_friedrichs guarantees D >= positivity_epsilon only for MoL::cfl <= " +
             std::to_string(bound) + " (1 / (2 x dimension)); with MoL::cfl = " + std::to_string(cfl) +
             " it also falls back to first-order mass fluxes in smooth flow");
}

}  // namespace remnant::grmhd
