#include "refinement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <utility>

#include "remnant/error.hpp"

namespace remnant::grid {

namespace {

double spacing(const GridConfig& c, int level, int d) {
  const auto ud = static_cast<std::size_t>(d);
  return (c.xmax[ud] - c.xmin[ud]) / static_cast<double>(c.ncells[ud]) / static_cast<double>(std::int64_t{1} << level);
}

// Does the block overlap the region (open intersection: touching is not overlapping)?
bool overlaps(const GridConfig& c, const BlockKey& key, const RefinementRegion& r) {
  std::array<double, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    if (d >= c.dimension) {
      lo[ud] = c.xmin[ud];
      hi[ud] = c.xmax[ud];
      continue;
    }
    const double h = spacing(c, key.level, d) * c.block_size[ud];
    lo[ud] = c.xmin[ud] + static_cast<double>(key.index[ud]) * h;
    hi[ud] = lo[ud] + h;
  }
  if (r.kind == RegionKind::box) {
    for (int d = 0; d < c.dimension; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      if (!(lo[ud] < r.bounds[2 * ud + 1] && hi[ud] > r.bounds[2 * ud])) return false;
    }
    return true;
  }
  // Sphere / shell: the range of Cartesian distances over the block, sampled on its cell
  // corners (enough at block granularity), with the exact closest point for Cartesian boxes.
  const Point3 centre{r.bounds[2], r.bounds[3], r.bounds[4]};
  double dmin = std::numeric_limits<double>::infinity(), dmax = 0;
  const int m[3] = {c.dimension > 0 ? c.block_size[0] : 0, c.dimension > 1 ? c.block_size[1] : 0,
                    c.dimension > 2 ? c.block_size[2] : 0};
  // Unused angles: sample the range (a 2D axisymmetric block is a ring).
  const int mu[3] = {m[0], c.dimension > 1 ? m[1] : (coords::is_angle(c.coordinates, 1) ? 8 : 0),
                     c.dimension > 2 ? m[2] : (coords::is_angle(c.coordinates, 2) ? 8 : 0)};
  for (int k = 0; k <= mu[2]; ++k)
    for (int j = 0; j <= mu[1]; ++j)
      for (int i = 0; i <= mu[0]; ++i) {
        const int idx[3] = {i, j, k};
        Point3 x{};
        for (std::size_t d = 0; d < 3; ++d)
          x[d] = mu[d] == 0 ? 0.5 * (lo[d] + hi[d]) : lo[d] + (hi[d] - lo[d]) * idx[d] / mu[d];
        const Point3 X = coords::to_cartesian(c.coordinates, x);
        const double dist = std::hypot(X[0] - centre[0], X[1] - centre[1], X[2] - centre[2]);
        dmin = std::min(dmin, dist);
        dmax = std::max(dmax, dist);
      }
  if (c.coordinates == CoordinateSystem::cartesian) {
    // The closest point of the box may lie inside a face.
    double s = 0;
    for (std::size_t d = 0; d < 3; ++d) {
      const double q = std::clamp(centre[d], lo[d], hi[d]) - centre[d];
      if (static_cast<int>(d) < c.dimension) s += q * q;
    }
    dmin = std::min(dmin, std::sqrt(s));
  }
  const double tol = 1e-12 * std::max(1.0, r.bounds[1]);
  return dmin < r.bounds[1] - tol && dmax > r.bounds[0] + tol;
}

struct Mesh {
  const GridConfig& config;
  const BoundaryMaps& maps;
  int dim;
  std::array<int, 3> n;

  // The level-l block across offset o (through the boundary maps); nullopt beyond an outflow face.
  std::optional<BlockIndex> neighbour(const BlockKey& k, const Offset& o) const {
    const auto seen = neighbour_seen(k, o);
    if (!seen) return std::nullopt;
    return seen->first;
  }
  // The same, with the offset as seen from the neighbour's side of a mirror (axis, origin,
  // reflection), so that the children next to the shared boundary are known.
  std::optional<std::pair<BlockIndex, Offset>> neighbour_seen(const BlockKey& k, const Offset& o) const {
    GlobalBox box;
    for (std::size_t d = 0; d < 3; ++d) {
      box.lo[d] = (k.index[d] + (static_cast<int>(d) < dim ? o[d] : 0)) * n[d];
      box.hi[d] = box.lo[d] + n[d];
    }
    const auto m = maps.image(k.level, {0, 0, 0}, box);
    if (!m) return std::nullopt;
    const GlobalBox im = m->apply(box);
    BlockIndex K{};
    Offset seen = o;
    for (std::size_t d = 0; d < 3; ++d) {
      K[d] = im.lo[d] / n[d];
      seen[d] = m->sigma[d] * o[d];
    }
    return std::make_pair(K, seen);
  }
};

BlockIndex parent_index(const BlockIndex& k, int dim) {
  BlockIndex p = k;
  for (int d = 0; d < dim; ++d) p[static_cast<std::size_t>(d)] /= 2;
  return p;
}

std::vector<BlockKey> children(const BlockKey& k, int dim) {
  std::vector<BlockKey> out;
  const int cz = dim >= 3 ? 2 : 1, cy = dim >= 2 ? 2 : 1;
  for (int c2 = 0; c2 < cz; ++c2)
    for (int c1 = 0; c1 < cy; ++c1)
      for (int c0 = 0; c0 < 2; ++c0) {
        BlockKey ch{k.level + 1, k.index};
        const int c[3] = {c0, c1, c2};
        for (int d = 0; d < dim; ++d) ch.index[static_cast<std::size_t>(d)] = 2 * k.index[static_cast<std::size_t>(d)] + c[d];
        out.push_back(ch);
      }
  return out;
}

// Whether child c of the neighbour K (seen across offset o, from K's side of any mirror)
// touches the block we look from: the child next to the shared face, edge or corner.
bool touches(const BlockKey& c, const BlockIndex& K, const Offset& o, int dim) {
  for (int d = 0; d < dim; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    const std::int64_t side = c.index[ud] - 2 * K[ud];  // 0: lower child, 1: upper child
    if (o[ud] > 0 && side != 0) return false;
    if (o[ud] < 0 && side != 1) return false;
  }
  return true;
}

}  // namespace

LevelBounds region_bounds(const GridConfig& config, const BlockKey& key) {
  LevelBounds b{0, config.max_level};
  int cap = config.max_level;
  for (const RefinementRegion& r : config.regions) {
    if (!overlaps(config, key, r)) continue;
    if (r.mode == RegionMode::at_least) b.min_level = std::max(b.min_level, r.level);
    else cap = std::min(cap, r.level);
  }
  b.max_level = cap;
  b.min_level = std::min(b.min_level, cap);
  return b;
}

std::vector<BlockKey> next_leaves(const GridConfig& config, const Forest& forest, const BoundaryMaps& maps,
                                  std::span<const int> wishes) {
  const int dim = forest.dimension();
  const Mesh mesh{config, maps, dim, forest.block_cells()};
  const std::int64_t total = forest.total_blocks();
  std::vector<int> target(static_cast<std::size_t>(total));
  for (std::int64_t g = 0; g < total; ++g) {
    const BlockKey& k = forest.key(g);
    const LevelBounds rb = region_bounds(config, k);
    int t = k.level + std::clamp(wishes[static_cast<std::size_t>(g)], -1, 1);
    t = std::max(t, rb.min_level);
    t = std::min(t, rb.max_level);
    target[static_cast<std::size_t>(g)] = std::clamp(t, k.level - 1, k.level + 1);
  }
  // Refinement, then the coarser neighbours that 2:1 balance drags along.
  std::vector<char> refine(static_cast<std::size_t>(total), 0);
  std::vector<std::int64_t> work;
  for (std::int64_t g = 0; g < total; ++g)
    if (target[static_cast<std::size_t>(g)] > forest.key(g).level) {
      refine[static_cast<std::size_t>(g)] = 1;
      work.push_back(g);
    }
  const auto offsets = neighbour_offsets(dim);
  while (!work.empty()) {
    const std::int64_t g = work.back();
    work.pop_back();
    const BlockKey k = forest.key(g);
    for (const Offset& o : offsets) {
      const auto K = mesh.neighbour(k, o);
      if (!K || k.level == 0 || forest.find(k.level, *K) >= 0) continue;
      const std::int64_t coarse = forest.find(k.level - 1, parent_index(*K, dim));
      if (coarse >= 0 && !refine[static_cast<std::size_t>(coarse)]) {
        refine[static_cast<std::size_t>(coarse)] = 1;
        work.push_back(coarse);
      }
    }
  }
  std::vector<BlockKey> refined;
  for (std::int64_t g = 0; g < total; ++g) {
    const BlockKey& k = forest.key(g);
    if (refine[static_cast<std::size_t>(g)]) {
      if (k.level >= config.max_level)
        throw RunError("Grid: 2:1 balance needs a block beyond Grid::max_level (internal error)");
      for (const BlockKey& c : children(k, dim)) refined.push_back(c);
    } else {
      refined.push_back(k);
    }
  }
  // Coarsening: complete families of unrefined leaves that all wish it, checked against the
  // mesh after refinement so that the parent never touches a block two levels finer.
  const Forest after(config, refined, 1);
  std::set<std::pair<int, BlockIndex>> merged;
  const std::size_t family = std::size_t{1} << dim;
  for (std::int64_t g = 0; g < total; ++g) {
    const BlockKey& k = forest.key(g);
    if (k.level == 0 || refine[static_cast<std::size_t>(g)] || target[static_cast<std::size_t>(g)] >= k.level) continue;
    const BlockKey parent{k.level - 1, parent_index(k.index, dim)};
    if (merged.count({parent.level, parent.index})) continue;
    bool ok = true;
    const auto sibs = children(parent, dim);
    for (const BlockKey& s : sibs) {
      const std::int64_t sg = forest.find(s.level, s.index);
      if (sg < 0 || refine[static_cast<std::size_t>(sg)] || target[static_cast<std::size_t>(sg)] >= s.level) ok = false;
    }
    if (!ok || sibs.size() != family) continue;
    if (region_bounds(config, parent).min_level > parent.level) continue;
    for (const Offset& o : offsets) {
      const auto seen = mesh.neighbour_seen(parent, o);
      if (!seen) continue;
      const BlockIndex K = seen->first;
      if (after.find(parent.level, K) >= 0) continue;
      if (parent.level > 0 && after.find(parent.level - 1, parent_index(K, dim)) >= 0) continue;
      for (const BlockKey& c : children(BlockKey{parent.level, K}, dim))
        if (touches(c, K, seen->second, dim) && after.find(c.level, c.index) < 0) ok = false;  // two levels finer
      if (!ok) break;
    }
    if (ok) merged.insert({parent.level, parent.index});
  }
  std::vector<BlockKey> out;
  for (const BlockKey& k : refined) {
    if (k.level > 0 && merged.count({k.level - 1, parent_index(k.index, dim)})) continue;
    out.push_back(k);
  }
  for (const auto& [level, index] : merged) out.push_back(BlockKey{level, index});
  return out;
}

std::string balance_violation(const GridConfig& config, const Forest& forest, const BoundaryMaps& maps) {
  const int dim = forest.dimension();
  const Mesh mesh{config, maps, dim, forest.block_cells()};
  for (const BlockKey& k : forest.leaves())
    for (const Offset& o : neighbour_offsets(dim)) {
      const auto seen = mesh.neighbour_seen(k, o);
      if (!seen) continue;
      const BlockIndex K = seen->first;
      if (forest.find(k.level, K) >= 0) continue;
      if (k.level > 0 && forest.find(k.level - 1, parent_index(K, dim)) >= 0) continue;
      bool ok = true;
      for (const BlockKey& c : children(BlockKey{k.level, K}, dim))
        if (touches(c, K, seen->second, dim)) ok &= forest.find(c.level, c.index) >= 0;
      if (!ok)
        return "block (level " + std::to_string(k.level) + ", " + std::to_string(k.index[0]) + " " +
               std::to_string(k.index[1]) + " " + std::to_string(k.index[2]) + ") has a neighbour two levels finer across (" +
               std::to_string(o[0]) + " " + std::to_string(o[1]) + " " + std::to_string(o[2]) + ")";
    }
  return "";
}

std::vector<BlockKey> initial_leaves(const GridConfig& config, const BoundaryMaps& maps) {
  std::vector<BlockKey> leaves = Forest::base_level(config);
  for (int pass = 0; pass <= 2 * config.max_level + 2; ++pass) {
    const Forest f(config, leaves, 1);
    const std::vector<int> keep(static_cast<std::size_t>(f.total_blocks()), 0);
    std::vector<BlockKey> next = next_leaves(config, f, maps, keep);
    const Forest g(config, next, 1);
    if (g.leaves() == f.leaves()) return leaves;
    leaves = g.leaves();
  }
  return leaves;
}

}  // namespace remnant::grid
