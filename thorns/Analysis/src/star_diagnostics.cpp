#include "Analysis/star_diagnostics.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <span>

#include "cell_distances.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::analysis {

StarDiagnostics star_diagnostics(Context& ctx) {
  using Cons = vars::HydroBase::cons;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double r_min = inf, centre[3] = {0, 0, 0};            // rho, alpha, psi at the cell nearest the origin
  double maxima[3] = {-inf, -inf, -inf};                 // rho_max, -alpha_min, psi_max
  if (!ctx.has_service("Analysis::cell_distances")) ctx.publish("Analysis::cell_distances", std::make_shared<CellDistances>());
  auto& distances = ctx.service<CellDistances>("Analysis::cell_distances");
  const std::span<Block* const> blocks = ctx.grid().local_blocks();
  for (std::size_t p = 0; p < blocks.size(); ++p) {
    Block* b = blocks[p];
    const double* cell_r = distances.of(blocks, p).data();
    using Prim = vars::HydroBase::prim;
    using Metric = vars::Spacetime::metric;
    const Prim prim(ctx, *b);
    const Metric metric(ctx, *b);
    const Field rho = prim.field(Prim::idx::rho);
    const Field psi = metric.field(Metric::idx::psi), alpha = metric.field(Metric::idx::alpha);
    for_interior(*b, [&](int i, int j, int k) {
      const double r = *cell_r++;
      // Ties (the cells around the origin of a 3D grid, equal up to round-off) take the largest
      // value, so that the result does not depend on which rank holds which of them.
      if (r < r_min) {
        r_min = r;
        centre[0] = rho(i, j, k), centre[1] = alpha(i, j, k), centre[2] = psi(i, j, k);
      } else if (r == r_min) {
        centre[0] = std::max(centre[0], rho(i, j, k)), centre[1] = std::max(centre[1], alpha(i, j, k));
        centre[2] = std::max(centre[2], psi(i, j, k));
      }
      maxima[0] = std::max(maxima[0], rho(i, j, k));
      maxima[1] = std::max(maxima[1], -alpha(i, j, k));
      maxima[2] = std::max(maxima[2], psi(i, j, k));
    });
  }
  MPI_Comm comm = ctx.grid().comm();
  double r_global;
  MPI_Allreduce(&r_min, &r_global, 1, MPI_DOUBLE, MPI_MIN, comm);
  // The rank(s) holding the nearest cells contribute their values (the largest of ties).
  double mine[3];
  for (int c = 0; c < 3; ++c) mine[c] = r_min == r_global ? centre[c] : -inf;
  double cg[3], mg[3];
  MPI_Allreduce(mine, cg, 3, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(maxima, mg, 3, MPI_DOUBLE, MPI_MAX, comm);
  // The grid's reduction sums block by block along the curve: the same bits on any rank count.
  const int cons = Cons::id(ctx);
  ctx.check_access(cons);
  const double mass_g = ctx.grid().reduce(cons, Cons::idx::D, ReductionKind::volume_integral);
  // HydroBase's mass budget: time-integrated boundary outflow and the D added by atmosphere/policy.
  using Budget = vars::HydroBase::mass_budget;
  const int budget = Budget::id(ctx);
  ctx.check_access(budget);
  const double outflow = ctx.grid().reduce(budget, Budget::idx::outflow, ReductionKind::volume_integral);
  const double source = ctx.grid().reduce(budget, Budget::idx::source, ReductionKind::volume_integral);
  StarDiagnostics d;
  d.iteration = ctx.iteration();
  d.time = ctx.time();
  d.rho_c = cg[0], d.alpha_c = cg[1], d.psi_c = cg[2];
  d.rho_max = mg[0], d.alpha_min = -mg[1], d.psi_max = mg[2];
  d.rest_mass = mass_g;
  d.outflow = outflow;
  d.atmosphere_source = source;
  d.mass_budget = mass_g + outflow - source;
  if (ctx.param<bool>("Analysis", "rotation")) {  // computed by Analysis_Rotation just before
    d.has_rotation = true;
    d.rotation = ctx.service<RotationDiagnostics>("Analysis::rotation_now");
  }
  return d;
}

std::string tsv_header(bool rotation, bool magnetic, bool collision) {
  std::string h = "# iteration\ttime\trho_c\trho_max\talpha_c\talpha_min\tpsi_c\tpsi_max\trest_mass\toutflow\t"
                  "atmosphere_source\tmass_budget";
  if (rotation) h += "\tJ\tT_over_W\tOmega_c\tM_komar\tmode_m1\tmode_m2";
  if (magnetic) h += "\tdivB_max\tE_mag\tE_mag_pol\tE_mag_tor\tB_max";
  if (collision)
    h += "\trho_max_norm\tM_rest_total\tM_adm\tM_komar_total\tquad_I\tquad_dI\th_plus\tz_rho_max_upper\t"
         "z_rho_max_lower\trho_max_point\trho_max_point_norm";
  return h + "\n";
}

std::string tsv_line(const StarDiagnostics& d) {
  char b[1536];
  int n = std::snprintf(b, sizeof b, "%lld\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g",
                        static_cast<long long>(d.iteration), d.time, d.rho_c, d.rho_max, d.alpha_c, d.alpha_min, d.psi_c,
                        d.psi_max, d.rest_mass, d.outflow, d.atmosphere_source, d.mass_budget);
  if (d.has_rotation) {
    const RotationDiagnostics& r = d.rotation;
    n += std::snprintf(b + n, sizeof b - static_cast<std::size_t>(n), "\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g", r.J,
                       r.T_over_W, r.omega_c, r.M_komar, r.mode_m1, r.mode_m2);
  }
  if (d.magnetic) {
    const MagneticDiagnostics& m = *d.magnetic;
    n += std::snprintf(b + n, sizeof b - static_cast<std::size_t>(n), "\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g", m.divB_max, m.E_mag,
                       m.E_mag_pol, m.E_mag_tor, m.B_max_gauss);
  }
  if (d.collision) {
    const CollisionDiagnostics& c = d.col;
    n += std::snprintf(b + n, sizeof b - static_cast<std::size_t>(n), "\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g",
                       d.rho_max_norm, c.M_rest, c.M_adm, c.M_komar, c.quad_I, c.quad_dI, d.h_plus, c.z_max_upper,
                       c.z_max_lower, c.rho_max_point, d.rho_max_point_norm);
  }
  return std::string(b) + "\n";
}

}  // namespace remnant::analysis
