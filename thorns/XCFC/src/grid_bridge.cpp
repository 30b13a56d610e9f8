#include "grid_bridge.hpp"

#include <mpi.h>

#include <cmath>

namespace remnant::xcfc {

GridShape shape_of_grid(const Context& ctx) {
  GridDriver& grid = ctx.grid();
  const auto blocks = grid.all_blocks();
  int level = blocks.empty() ? 0 : blocks.front().level;
  for (const auto& b : blocks)
    if (b.level != level)
      throw RunError("XCFC solves on a uniform grid; this grid has blocks on levels " + std::to_string(level) + " and " +
                     std::to_string(b.level) + ". Run with Grid::max_level = 0 (composite AMR solves are not implemented)");
  GridShape s;
  s.coordinates = grid.coordinates();
  s.dimension = grid.dimension();
  const auto& n = ctx.param<std::vector<std::int64_t>>("Grid", "ncells");
  const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& hi = ctx.param<std::vector<double>>("Grid", "xmax");
  const auto& bl = ctx.param<std::vector<std::string>>("Grid", "boundary_lower");
  const auto& bu = ctx.param<std::vector<std::string>>("Grid", "boundary_upper");
  auto kind = [](const std::string& k) {
    if (k == "outflow") return Boundary::outer;
    if (k == "reflect") return Boundary::reflect;
    if (k == "axis") return Boundary::axis;
    if (k == "origin") return Boundary::origin;
    throw RunError("XCFC: Grid boundary '" + k + "' is not supported by the elliptic solver (periodic domains have no far field)");
  };
  for (int d = 0; d < 3; ++d) {
    if (d < s.dimension) {
      s.n[d] = static_cast<int>(n[static_cast<std::size_t>(d)]) << level;
      s.lo[d] = lo[static_cast<std::size_t>(d)];
      s.dx[d] = (hi[static_cast<std::size_t>(d)] - lo[static_cast<std::size_t>(d)]) / s.n[d];
      s.boundary[d] = {kind(bl[static_cast<std::size_t>(d)]), kind(bu[static_cast<std::size_t>(d)])};
    } else {
      s.n[d] = 1;
      s.boundary[d] = {Boundary::outer, Boundary::outer};
    }
  }
  return s;
}

GridBridge::GridBridge(Context& ctx, const GridShape& shape) : ctx_(ctx), shape_(shape) {}

std::size_t GridBridge::global_index(const Block& b, int i, int j, int k) const {
  const std::int64_t I = b.index[0] * b.n[0] + i, J = b.index[1] * b.n[1] + j, K = b.index[2] * b.n[2] + k;
  return static_cast<std::size_t>(I + shape_.n[0] * (J + static_cast<std::int64_t>(shape_.n[1]) * K));
}

void GridBridge::allreduce(std::vector<double>& a) const {
  if (ctx_.nranks() > 1)
    MPI_Allreduce(MPI_IN_PLACE, a.data(), static_cast<int>(a.size()), MPI_DOUBLE, MPI_SUM, ctx_.grid().comm());
}

std::vector<double> GridBridge::gather(int group, int comp) const {
  return gather_cells([&](Block& b, int i, int j, int k) { return b.field(group, comp)(i, j, k); });
}

void GridBridge::scatter(const std::vector<double>& a, int group, int comp) const {
  for (Block* b : ctx_.grid().local_blocks()) {
    Field f = b->field(group, comp);
    for_interior(*b, [&](int i, int j, int k) { f(i, j, k) = a[global_index(*b, i, j, k)]; });
  }
}

}  // namespace remnant::xcfc
