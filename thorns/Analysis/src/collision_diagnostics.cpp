#include "Analysis/collision_diagnostics.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::analysis {
namespace {

constexpr int n_integrals = 5;  // M_rest, M_adm, M_komar, quad_I, quad_dI

// The direction of z (the collision axis): Cartesian z, cylindrical z; spherical grids use
// the polar axis through to_cartesian, with the halves by the sign of Z.
double cartesian_z(const Point3& X) { return X[2]; }

}  // namespace

bool collision_diagnostics_enabled(const Context& ctx) {
  const auto& mode = ctx.param<std::string>("Analysis", "collision_diagnostics");
  if (mode == "always") return true;
  if (mode == "never") return false;
  const auto& active = ctx.active_thorns();
  return std::find(active.begin(), active.end(), "HeadOn") != active.end();
}

double symmetry_factor(const Context& ctx) {
  const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& hi = ctx.param<std::vector<double>>("Grid", "xmax");
  const auto& blo = ctx.param<std::vector<std::string>>("Grid", "boundary_lower");
  const auto& bhi = ctx.param<std::vector<std::string>>("Grid", "boundary_upper");
  const auto dim = static_cast<std::size_t>(ctx.param<std::int64_t>("Grid", "dimension"));
  const bool cartesian = ctx.param<std::string>("Grid", "coordinates") == "cartesian";
  const bool cylindrical = ctx.param<std::string>("Grid", "coordinates") == "cylindrical";
  double f = 1;
  for (std::size_t d = 0; d < dim; ++d) {
    // Planes of reflection symmetry through 0: every Cartesian direction, and cylindrical z.
    if (!(cartesian || (cylindrical && d == 1))) continue;
    if (blo[d] == "reflect" && lo[d] == 0) f *= 2;
    if (bhi[d] == "reflect" && hi[d] == 0) f *= 2;
  }
  // Spherical grids: the equator theta = pi/2 as the upper theta boundary.
  const bool spherical = ctx.param<std::string>("Grid", "coordinates") == "spherical";
  if (spherical && dim >= 2 && bhi[1] == "reflect" && std::abs(hi[1] - 0.5 * std::numbers::pi) < 1e-12) f *= 2;
  return f;
}

CollisionDiagnostics collision_diagnostics(Context& ctx) {
  using Prim = vars::HydroBase::prim;
  using Cons = vars::HydroBase::cons;
  using Metric = vars::Spacetime::metric;
  constexpr double inf = std::numeric_limits<double>::infinity();
  GridDriver& grid = ctx.grid();
  const std::size_t nblocks = grid.all_blocks().size();
  std::vector<double> partial(nblocks * n_integrals, 0.0);
  double best[2] = {-inf, -inf};  // density maxima in z <= 0, z > 0
  for (Block* b : grid.local_blocks()) {
    if (b->gid < 0 || static_cast<std::size_t>(b->gid) >= nblocks)
      throw RunError("Analysis: block id " + std::to_string(b->gid) + " outside the grid's " + std::to_string(nblocks));
    const Prim prim(ctx, *b);
    const Cons cons(ctx, *b);
    const Metric metric(ctx, *b);
    const CoordinateSystem cs = b->coordinates;
    double s[n_integrals] = {0, 0, 0, 0, 0};
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 x = cell_point(*b, i, j, k);
      const Point3 X = coords::to_cartesian(cs, x);
      const double dv = b->cell_volume(i, j, k);
      const double psi = metric.psi(i, j, k), psi2 = psi * psi, psi6 = psi2 * psi2 * psi2;
      const double D = cons.D(i, j, k), E = D + cons.tau(i, j, k);
      double Sv = 0, betaS = 0, Sxi = 0;
      const Point3 xi = coords::vector_from_cartesian(cs, x, {-X[0], -X[1], 2 * X[2]});
      for (int d = 0; d < 3; ++d) {
        const double Sd = cons.S(d, i, j, k);
        Sv += Sd * prim.vel(d, i, j, k);
        betaS += metric.beta(d, i, j, k) * Sd;
        Sxi += Sd * xi[static_cast<std::size_t>(d)];
      }
      const double S_trace = Sv + 3 * psi6 * prim.press(i, j, k);
      s[0] += D * dv;
      s[1] += E / psi * dv;
      s[2] += (metric.alpha(i, j, k) * (E + S_trace) - 2 * betaS) * dv;
      s[3] += D * (X[2] * X[2] - 0.5 * (X[0] * X[0] + X[1] * X[1])) * dv;
      s[4] += Sxi * dv;
      const int h = cartesian_z(X) > 0 ? 1 : 0;
      best[h] = std::max(best[h], prim.rho(i, j, k));
    });
    std::copy(s, s + n_integrals, partial.begin() + static_cast<std::ptrdiff_t>(b->gid) * n_integrals);
  }
  MPI_Comm comm = grid.comm();
  // Each block's sums come from its owner (others hold 0, and x + 0 = x exactly); adding the blocks
  // in their global order gives the same bits on any rank count.
  MPI_Allreduce(MPI_IN_PLACE, partial.data(), static_cast<int>(partial.size()), MPI_DOUBLE, MPI_SUM, comm);
  double total[n_integrals] = {0, 0, 0, 0, 0};
  for (std::size_t g = 0; g < nblocks; ++g)
    for (int q = 0; q < n_integrals; ++q) total[q] += partial[g * n_integrals + static_cast<std::size_t>(q)];
  double gbest[2];
  MPI_Allreduce(best, gbest, 2, MPI_DOUBLE, MPI_MAX, comm);
  // Where the maxima are: the smallest |z| among the cells holding them (ties on mirror cells).
  double where[2] = {inf, inf};
  for (Block* b : grid.local_blocks()) {
    const Prim prim(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const double z = cartesian_z(coords::to_cartesian(b->coordinates, cell_point(*b, i, j, k)));
      const int h = z > 0 ? 1 : 0;
      if (prim.rho(i, j, k) == gbest[h]) where[h] = std::min(where[h], std::abs(z));
    });
  }
  double gwhere[2];
  MPI_Allreduce(where, gwhere, 2, MPI_DOUBLE, MPI_MIN, comm);
  const double f = symmetry_factor(ctx);
  CollisionDiagnostics c;
  c.M_rest = f * total[0];
  c.M_adm = f * total[1];
  c.M_komar = f * total[2];
  c.quad_I = f * total[3];
  c.quad_dI = f * total[4];
  c.rho_max_upper = std::isfinite(gbest[1]) ? gbest[1] : 0.0;
  c.z_max_upper = std::isfinite(gwhere[1]) ? gwhere[1] : 0.0;
  c.z_max_lower = std::isfinite(gwhere[0]) ? -gwhere[0] : -c.z_max_upper;  // the mirror without cells at z <= 0
  c.rho_max_point = rho_max_point(ctx);
  return c;
}

}  // namespace remnant::analysis
