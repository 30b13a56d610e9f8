#include "edge_correction.hpp"

#include <string>

#include "remnant/comm_counters.hpp"
#include "remnant/error.hpp"

namespace remnant::grid {

namespace {

// The block boundary towards offset o, for edges of staggering s: the neighbouring cells across
// it and the edge points on it (global indices of the block's level). False when the edges do
// not lie on that boundary (they sit at cell centres in a direction of o).
bool boundary_towards(const Offset& o, const std::array<int, 3>& s, const Range& origin, const std::array<int, 3>& n,
                      int dim, GlobalBox& cells, GlobalBox& points) {
  for (int d = 0; d < dim; ++d)
    if (o[static_cast<std::size_t>(d)] != 0 && s[static_cast<std::size_t>(d)] == 0) return false;
  for (std::size_t e = 0; e < 3; ++e) {
    const bool used = static_cast<int>(e) < dim;
    const int oe = o[e];
    cells.lo[e] = oe < 0 ? origin[e] - 1 : (oe > 0 ? origin[e] + n[e] : origin[e]);
    cells.hi[e] = oe == 0 ? origin[e] + (used ? n[e] : 1) : cells.lo[e] + 1;
    points.lo[e] = oe > 0 ? origin[e] + n[e] : origin[e];
    points.hi[e] = oe == 0 ? origin[e] + (used ? n[e] + s[e] : 1) : points.lo[e] + 1;
  }
  return true;
}

}  // namespace

EdgeCorrection::EdgeCorrection(const Forest& forest, const BoundaryMaps& maps, std::span<Block* const> blocks,
                               int rank, MPI_Comm comm, const std::array<int, 3>& stagger)
    : comm_(comm), dimension_(forest.dimension()), stagger_(stagger), blocks_(blocks.begin(), blocks.end()),
      first_gid_(forest.first_gid(rank)), count_(forest.block_count(rank)) {
  fine_.fine = true;
  // Enumerated over the whole mesh in gid order, so that both sides agree on message layouts.
  for (std::int64_t gid = 0; gid < forest.total_blocks(); ++gid) {
    plan_same_level(forest, maps, gid);
    plan_finer(forest, maps, gid);
  }
  check_sources(same_, forest.block_cells());
  check_sources(fine_, forest.block_cells());
  sort_out(same_, forest);
  sort_out(fine_, forest);
}

// Every value read must be an edge of the source block's interior (block faces included): a plan
// that reaches outside would read another allocation's memory, whose content changes from run to
// run (the heap layout differs, most under MPI).
void EdgeCorrection::check_sources(const Pass& pass, const std::array<int, 3>& n) const {
  for (const Transfer& t : pass.all)
    for (const auto& p : t.points)
      for (int e = 0; e < dimension_; ++e) {
        const auto ue = static_cast<std::size_t>(e);
        const int q = (pass.fine ? 2 * p[ue] : p[ue]) + t.shift[ue];
        const int last = n[ue] + stagger_[ue] - 1 - (pass.fine && !stagger_[ue] ? 1 : 0);
        if (q < 0 || q > last)
          throw RunError("Grid: internal error: correct_edges would read edge " + std::to_string(q) + " in direction " +
                         std::to_string(e) + " of block " + std::to_string(t.src_gid) + " (valid 0.." +
                         std::to_string(last) + ") for block " + std::to_string(t.dst_gid));
      }
}

void EdgeCorrection::plan_same_level(const Forest& forest, const BoundaryMaps& maps, std::int64_t gid) {
  const BlockKey& key = forest.key(gid);
  const auto& n = forest.block_cells();
  const Range origin = forest.origin(key);
  // Per boundary point of this block: the lowest gid among the same-level blocks that share it.
  std::map<std::array<int, 3>, std::pair<std::int64_t, std::array<int, 3>>> best;
  bool involved = is_mine(gid);
  for (const Offset& o : neighbour_offsets(dimension_)) {
    GlobalBox cells, points;
    if (!boundary_towards(o, stagger_, origin, n, dimension_, cells, points)) continue;
    const auto map = maps.image(key.level, {0, 0, 0}, cells);
    if (!map || !map->preserves_orientation() || map->mirrored) continue;
    const GlobalBox image = map->apply(cells);
    BlockIndex K{};
    for (std::size_t e = 0; e < 3; ++e) K[e] = image.lo[e] / n[e];
    const std::int64_t other = forest.find(key.level, K);
    if (other < 0 || other >= gid) continue;
    involved = involved || is_mine(other);
    const Range other_origin = forest.origin(forest.key(other));
    std::array<int, 3> shift{};
    for (std::size_t e = 0; e < 3; ++e) shift[e] = static_cast<int>(origin[e] + map->shift[e] - other_origin[e]);
    for (std::int64_t k = points.lo[2]; k < points.hi[2]; ++k)
      for (std::int64_t j = points.lo[1]; j < points.hi[1]; ++j)
        for (std::int64_t i = points.lo[0]; i < points.hi[0]; ++i) {
          const std::array<int, 3> p{static_cast<int>(i - origin[0]), static_cast<int>(j - origin[1]),
                                     static_cast<int>(k - origin[2])};
          auto it = best.find(p);
          if (it == best.end() || other < it->second.first) best[p] = {other, shift};
        }
  }
  if (!involved || best.empty()) return;
  // One transfer per source and shift: across a periodic direction with two blocks the same
  // neighbour lies beyond both faces, each with its own shift (one shared shift made the points
  // of one face read outside the source block).
  std::map<std::pair<std::int64_t, std::array<int, 3>>, Transfer> by_source;
  for (const auto& [p, src] : best) {
    Transfer& t = by_source[src];
    t.src_gid = src.first;
    t.dst_gid = gid;
    t.shift = src.second;
    t.points.push_back(p);
  }
  for (auto& [g, t] : by_source)
    if (is_mine(t.src_gid) || is_mine(t.dst_gid)) same_.all.push_back(std::move(t));
}

void EdgeCorrection::plan_finer(const Forest& forest, const BoundaryMaps& maps, std::int64_t gid) {
  const BlockKey& ck = forest.key(gid);
  const int l = ck.level, dim = dimension_;
  if (l >= forest.finest_level()) return;
  const auto& n = forest.block_cells();
  const Range origin = forest.origin(ck);
  for (const Offset& o : neighbour_offsets(dim)) {
    GlobalBox cells, points;
    if (!boundary_towards(o, stagger_, origin, n, dim, cells, points)) continue;
    const auto map = maps.image(l, {0, 0, 0}, cells);
    if (!map || !map->preserves_orientation() || map->mirrored) continue;
    const GlobalBox image = map->apply(cells);
    BlockIndex K{};
    for (std::size_t e = 0; e < 3; ++e) K[e] = image.lo[e] / n[e];
    if (forest.find(l, K) >= 0) continue;
    BlockIndex Kc = K;
    for (int e = 0; e < dim; ++e) Kc[static_cast<std::size_t>(e)] /= 2;
    if (l > 0 && forest.find(l - 1, Kc) >= 0) continue;
    const GlobalBox point_image = map->apply(points);
    const int cz = dim >= 3 ? 2 : 1, cy = dim >= 2 ? 2 : 1;
    for (int c2 = 0; c2 < cz; ++c2)
      for (int c1 = 0; c1 < cy; ++c1)
        for (int c0 = 0; c0 < 2; ++c0) {
          const int c[3] = {c0, c1, c2};
          // The child's points, in level-l indices of the image frame.
          const auto [Kf, cover] = forest.child_cover(K, c, stagger_);
          const GlobalBox part = intersect(point_image, cover);
          if (part.empty()) continue;
          const std::int64_t fine = forest.find(l + 1, Kf);
          if (fine < 0) throw RunError("Grid: internal error: correct_edges found no fine leaf (mesh not 2:1 balanced)");
          if (!is_mine(fine) && !is_mine(gid)) continue;
          Transfer t;
          t.src_gid = fine;
          t.dst_gid = gid;
          for (std::size_t e = 0; e < 3; ++e)
            if (static_cast<int>(e) < dim) t.shift[e] = static_cast<int>(2 * (origin[e] + map->shift[e]) - Kf[e] * n[e]);
          for (std::int64_t k = part.lo[2]; k < part.hi[2]; ++k)
            for (std::int64_t j = part.lo[1]; j < part.hi[1]; ++j)
              for (std::int64_t i = part.lo[0]; i < part.hi[0]; ++i)
                t.points.push_back({static_cast<int>(i - map->shift[0] - origin[0]),
                                    static_cast<int>(j - map->shift[1] - origin[1]),
                                    static_cast<int>(k - map->shift[2] - origin[2])});
          fine_.all.push_back(std::move(t));
        }
  }
}

void EdgeCorrection::sort_out(Pass& pass, const Forest& forest) {
  for (const Transfer& t : pass.all) {
    const bool src_mine = is_mine(t.src_gid), dst_mine = is_mine(t.dst_gid);
    if (src_mine && dst_mine) {
      pass.local.push_back(&t);
    } else if (src_mine) {
      pass.sends[forest.owner(t.dst_gid)].push_back(&t);
      pass.send_values += t.points.size();
    } else {
      pass.recvs[forest.owner(t.src_gid)].push_back(&t);
      pass.recv_values += t.points.size();
    }
  }
}

void EdgeCorrection::source_values(const Pass& pass, const Transfer& t, const Field& f, double* out) const {
  int along = -1;  // the direction an edge runs along (none for edges along an unused direction)
  for (int e = 0; e < dimension_; ++e)
    if (!stagger_[static_cast<std::size_t>(e)]) along = e;
  for (const auto& p : t.points) {
    int q[3];
    for (int e = 0; e < 3; ++e) q[e] = (pass.fine && e < dimension_ ? 2 * p[static_cast<std::size_t>(e)] : p[static_cast<std::size_t>(e)]) + t.shift[static_cast<std::size_t>(e)];
    double v = f(q[0], q[1], q[2]);
    if (pass.fine && along >= 0) {
      q[along] += 1;
      v = 0.5 * (v + f(q[0], q[1], q[2]));
    }
    *out++ = v;
  }
}

void EdgeCorrection::run_pass(Pass& pass, const VariableRegistry& vars, std::span<const int> groups) {
  std::size_t ncomp = 0;
  for (int g : groups) ncomp += static_cast<std::size_t>(vars.group(g).ncomp());
  auto pack = [&](const Transfer& t, double* out) {
    Block& src = local_block(t.src_gid);
    for (int g : groups)
      for (int comp = 0; comp < vars.group(g).ncomp(); ++comp) {
        source_values(pass, t, src.field(g, comp), out);
        out += t.points.size();
      }
    return out;
  };
  auto unpack = [&](const Transfer& t, const double* in) {
    Block& dst = local_block(t.dst_gid);
    for (int g : groups)
      for (int comp = 0; comp < vars.group(g).ncomp(); ++comp) {
        const Field f = dst.field(g, comp);
        for (const auto& p : t.points) f(p[0], p[1], p[2]) = *in++;
      }
    return in;
  };
  send_buffer_.resize(pass.send_values * ncomp);
  recv_buffer_.resize(pass.recv_values * ncomp);
  std::vector<MPI_Request> requests;
  double* in = recv_buffer_.data();
  for (auto& [r, ts] : pass.recvs) {
    std::size_t count = 0;
    for (const Transfer* t : ts) count += t->points.size() * ncomp;
    requests.emplace_back();
    MPI_Irecv(in, static_cast<int>(count), MPI_DOUBLE, r, pass.fine ? 3 : 2, comm_, &requests.back());
    in += count;
  }
  double* out = send_buffer_.data();
  for (auto& [r, ts] : pass.sends) {
    double* start = out;
    for (const Transfer* t : ts) out = pack(*t, out);
    requests.emplace_back();
    MPI_Isend(start, static_cast<int>(out - start), MPI_DOUBLE, r, pass.fine ? 3 : 2, comm_, &requests.back());
  }
  comm::count("edge_correction", comm::Pattern::p2p, -1, static_cast<long long>(pass.sends.size()),
              static_cast<long long>(sizeof(double) * static_cast<std::size_t>(out - send_buffer_.data())));
  // Same-level sources never change in this pass (they hold the lowest gid of their points).
  for (const Transfer* t : pass.local) {
    scratch_.resize(t->points.size() * ncomp);
    pack(*t, scratch_.data());
    unpack(*t, scratch_.data());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  const double* pos = recv_buffer_.data();
  for (auto& [r, ts] : pass.recvs)
    for (const Transfer* t : ts) pos = unpack(*t, pos);
}

void EdgeCorrection::run(const VariableRegistry& vars, std::span<const int> edge_groups) {
  run_pass(same_, vars, edge_groups);
  run_pass(fine_, vars, edge_groups);
}

}  // namespace remnant::grid
