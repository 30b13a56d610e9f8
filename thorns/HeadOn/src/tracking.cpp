#include "tracking.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "remnant/vars/HydroBase.hpp"

namespace remnant::headon {
namespace {

// The z coordinate's direction: Cartesian (x, y, z) or cylindrical (R, z).
int z_dir(const Block& b) { return b.coordinates == CoordinateSystem::cartesian ? 2 : 1; }

// Distance of the block (its faces) from the point (0, 0, zc) on the axis.
double block_distance(const Block& b, double zc) {
  auto gap = [&](int d, double x) {
    const double lo = b.face_coordinate(d, 0), hi = b.face_coordinate(d, b.n[d]);
    return x < lo ? lo - x : (x > hi ? x - hi : 0.0);
  };
  const int dz = z_dir(b);
  double s = gap(dz, zc) * gap(dz, zc);
  if (b.coordinates == CoordinateSystem::cartesian)
    s += gap(0, 0.0) * gap(0, 0.0) + gap(1, 0.0) * gap(1, 0.0);
  else
    s += gap(0, 0.0) * gap(0, 0.0);  // R >= 0
  return std::sqrt(s);
}

}  // namespace

Centres& centres(Context& ctx) {
  if (!ctx.has_service("HeadOn::centres")) {
    auto c = std::make_shared<Centres>();
    const double d = ctx.param<double>("HeadOn", "separation");
    c->z = {-0.5 * d, 0.5 * d};
    const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
    const bool cartesian = ctx.param<std::string>("Grid", "coordinates") == "cartesian";
    c->lower_in_grid = lo[cartesian ? 2 : 1] < 0;
    ctx.publish("HeadOn::centres", c);
  }
  return ctx.service<Centres>("HeadOn::centres");
}

void track_stars(Context& ctx) {
  Centres& c = centres(ctx);
  constexpr double inf = std::numeric_limits<double>::infinity();
  using Prim = vars::HydroBase::prim;
  // Per half (z <= 0, z > 0): the largest density, then the smallest |z| among the cells holding it
  // (ties, e.g. mirror cells of a full grid, give the same answer on any rank count).
  double best[2] = {-inf, -inf};
  for (Block* b : ctx.grid().local_blocks()) {
    const Field rho = Prim(ctx, *b).field(Prim::idx::rho);
    const int dz = z_dir(*b);
    for_interior(*b, [&](int i, int j, int k) {
      const int ijk[3] = {i, j, k};
      const int h = b->centroid(dz, ijk[dz]) > 0 ? 1 : 0;
      best[h] = std::max(best[h], rho(i, j, k));
    });
  }
  double gbest[2];
  MPI_Allreduce(best, gbest, 2, MPI_DOUBLE, MPI_MAX, ctx.grid().comm());
  double where[2] = {inf, inf};  // |z| of the maximum
  for (Block* b : ctx.grid().local_blocks()) {
    const Field rho = Prim(ctx, *b).field(Prim::idx::rho);
    const int dz = z_dir(*b);
    for_interior(*b, [&](int i, int j, int k) {
      const int ijk[3] = {i, j, k};
      const double z = b->centroid(dz, ijk[dz]);
      const int h = z > 0 ? 1 : 0;
      if (rho(i, j, k) == gbest[h]) where[h] = std::min(where[h], std::abs(z));
    });
  }
  double gwhere[2];
  MPI_Allreduce(where, gwhere, 2, MPI_DOUBLE, MPI_MIN, ctx.grid().comm());
  if (std::isfinite(gwhere[1])) c.z[1] = gwhere[1];
  if (c.lower_in_grid && std::isfinite(gwhere[0])) c.z[0] = -gwhere[0];
  if (!c.lower_in_grid) c.z[0] = -c.z[1];
}

int wanted_level(const Block& b, const Centres& c, const std::vector<double>& radii) {
  const double dist = std::min(block_distance(b, c.z[0]), block_distance(b, c.z[1]));
  int level = 0;
  for (double r : radii)
    if (dist < r) ++level;
  return level;
}

void register_criterion(Context& ctx) {
  const auto& radii = ctx.param<std::vector<double>>("HeadOn", "refine_radii");
  if (radii.empty()) return;
  Context* c = &ctx;
  ctx.grid().add_refinement_criterion("HeadOn::density_tracking", [c, radii](Block& b) {
    const int want = wanted_level(b, centres(*c), radii);
    return b.level < want ? 1 : (b.level > want ? -1 : 0);
  });
}

}  // namespace remnant::headon
