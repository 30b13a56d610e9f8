#include "grid_bridge.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include "remnant/comm_counters.hpp"

namespace remnant::xcfc {

void check_face(const Domain& domain, int d, int side) {
  const auto u = static_cast<std::size_t>(d);
  const Boundary b = domain.faces.boundary[u][static_cast<std::size_t>(side)];
  if (b == Boundary::outflow || b == Boundary::reflect || b == Boundary::axis || b == Boundary::origin) return;
  // Periodic is phi of a 3D cylindrical or spherical grid only: elsewhere there is no far field.
  if (b == Boundary::periodic && d == 2 && domain.faces.coordinates != CoordinateSystem::cartesian &&
      std::abs(domain.hi[u] - domain.lo[u] - 2 * std::numbers::pi) < 1e-12)
    return;
  throw std::invalid_argument(std::string("XCFC: Grid boundary '") + (b == Boundary::periodic ? "periodic" : "interface") +
                              "' in direction " + std::to_string(d) +
                              " is not supported by the elliptic solver (allowed: outflow, reflect, axis, origin; "
                              "periodic only for phi over [0, 2 pi] of a 3D cylindrical or spherical grid: other "
                              "periodic domains have no far field)");
}

CompositeLayout layout_of_grid(const Context& ctx) {
  GridDriver& grid = ctx.grid();
  const Domain domain = grid.domain();
  CompositeLayout lay;
  GridShape& s = lay.base;
  s.coordinates = domain.faces.coordinates;
  s.dimension = domain.faces.dimension;
  for (int d = 0; d < 3; ++d) {
    const auto u = static_cast<std::size_t>(d);
    if (d < s.dimension) {
      for (int side = 0; side < 2; ++side) {
        try {
          check_face(domain, d, side);
        } catch (const std::invalid_argument& e) {
          throw RunError(e.what());
        }
      }
      s.n[d] = static_cast<int>(domain.cells[u]);
      s.lo[d] = domain.lo[u];
      s.dx[d] = (domain.hi[u] - domain.lo[u]) / s.n[d];
      s.boundary[d] = domain.faces.boundary[u];
      lay.patch_cells[d] = domain.block_cells[u];
    } else {
      s.n[d] = 1;
      s.boundary[d] = {Boundary::outer, Boundary::outer};
      lay.patch_cells[d] = 1;
    }
  }
  // Level l >= 1: every leaf of level l and every ancestor on level l of a finer leaf.
  std::vector<std::set<std::array<std::int64_t, 3>>> levels;
  for (const BlockKey& k : grid.all_blocks()) {
    std::array<std::int64_t, 3> idx = k.index;
    for (int l = k.level; l >= 1; --l) {
      if (static_cast<int>(levels.size()) < l) levels.resize(static_cast<std::size_t>(l));
      levels[static_cast<std::size_t>(l - 1)].insert(idx);
      for (int d = 0; d < s.dimension; ++d) idx[static_cast<std::size_t>(d)] /= 2;
    }
  }
  for (const auto& set : levels) {
    lay.patches.emplace_back();
    for (const auto& b : set)
      lay.patches.back().push_back({static_cast<int>(b[0] * lay.patch_cells[0]), static_cast<int>(b[1] * lay.patch_cells[1]),
                                    static_cast<int>(b[2] * lay.patch_cells[2])});
  }
  return lay;
}

GridBridge::GridBridge(Context& ctx, const CompositeMultigrid& mg) : ctx_(ctx), mg_(mg) {
  const CompositeLayout& lay = mg.layout();
  int part = 1;
  for (const auto& level : lay.patches) {
    part_of_block_.emplace_back();
    for (const auto& c : level) {
      std::array<std::int64_t, 3> b{};
      for (int d = 0; d < 3; ++d) b[static_cast<std::size_t>(d)] = c[static_cast<std::size_t>(d)] / lay.patch_cells[static_cast<std::size_t>(d)];
      part_of_block_.back()[b] = part++;
    }
  }
}

GridBridge::Place GridBridge::place(const Block& b) const {
  if (b.level == 0) {
    const GridShape& s = mg_.base_shape();
    return {0, {b.index[0] * b.n[0], b.index[1] * b.n[1], b.index[2] * b.n[2]}, s.n[0], s.n[1]};
  }
  const auto& map = part_of_block_.at(static_cast<std::size_t>(b.level - 1));
  const auto it = map.find(b.index);
  if (it == map.end()) throw RunError("XCFC: internal error: a block of level " + std::to_string(b.level) + " is not in the composite layout");
  return {it->second, {0, 0, 0}, b.n[0], b.n[1]};
}

void GridBridge::complete(CompositeField& f) const {
  if (ctx_.nranks() > 1) {
    // The base part in place (no copies of the largest part), the patches flattened into one
    // message. Every cell has one nonzero term, so the sums are exact in any grouping.
    const MPI_Comm comm = ctx_.grid().comm();
    std::vector<double>& base = f.part.at(0);
    MPI_Allreduce(MPI_IN_PLACE, base.data(), static_cast<int>(base.size()), MPI_DOUBLE, MPI_SUM, comm);
    comm::count("xcfc_bridge_allreduce", comm::Pattern::allreduce, 0, 1, static_cast<long long>(sizeof(double) * base.size()));
    if (f.part.size() > 1) {
      std::vector<double> flat;
      for (std::size_t n = 1; n < f.part.size(); ++n) flat.insert(flat.end(), f.part[n].begin(), f.part[n].end());
      MPI_Allreduce(MPI_IN_PLACE, flat.data(), static_cast<int>(flat.size()), MPI_DOUBLE, MPI_SUM, comm);
      comm::count("xcfc_bridge_allreduce", comm::Pattern::allreduce, 1, 1, static_cast<long long>(sizeof(double) * flat.size()));
      std::size_t at = 0;
      for (std::size_t n = 1; n < f.part.size(); ++n) {
        auto& p = f.part[n];
        std::copy(flat.begin() + static_cast<std::ptrdiff_t>(at), flat.begin() + static_cast<std::ptrdiff_t>(at + p.size()), p.begin());
        at += p.size();
      }
    }
  }
  mg_.fill_covered(f);
}

CompositeField GridBridge::gather(int group, int comp) const {
  return gather_cells([&](Block& b) { return b.field(group, comp); });
}

void GridBridge::scatter(const CompositeField& a, int group, int comp) const {
  for (Block* b : ctx_.grid().local_blocks()) {
    const Place pl = place(*b);
    const std::vector<double>& part = a.part.at(static_cast<std::size_t>(pl.part));
    Field f = b->field(group, comp);
    for_interior(*b, [&](int i, int j, int k) { f(i, j, k) = part[pl.index(i, j, k)]; });
  }
}

}  // namespace remnant::xcfc
