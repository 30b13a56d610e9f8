#include "regrid.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <tuple>

#include "face_prolongation.hpp"
#include "ghost_plan.hpp"
#include "remnant/comm_counters.hpp"
#include "remnant/error.hpp"
#include "transfer.hpp"

namespace remnant::grid {

namespace {

enum class Source { same, parent, children };

struct Origin {
  Source kind;
  std::vector<std::int64_t> old_gids;
  // Prolonged blocks: same-level leaves of the old mesh across a face (direction, upper, old gid).
  std::vector<std::tuple<int, bool, std::int64_t>> kept_faces;
};

// The same-level leaves of the old mesh across the faces of new block k (periodic faces
// included; mirror faces lead back to the block's own range or to zero-area faces).
std::vector<std::tuple<int, bool, std::int64_t>> kept_face_neighbours(const Forest& old_forest, const BoundaryMaps& maps,
                                                                      const BlockKey& k) {
  std::vector<std::tuple<int, bool, std::int64_t>> out;
  const auto& n = old_forest.block_cells();
  for (int d = 0; d < old_forest.dimension(); ++d)
    for (const bool upper : {false, true}) {
      const auto ud = static_cast<std::size_t>(d);
      GlobalBox cell;
      for (std::size_t e = 0; e < 3; ++e) {
        cell.lo[e] = k.index[e] * n[e];
        cell.hi[e] = cell.lo[e] + 1;
      }
      cell.lo[ud] = upper ? (k.index[ud] + 1) * n[ud] : k.index[ud] * n[ud] - 1;
      cell.hi[ud] = cell.lo[ud] + 1;
      const auto map = maps.image(k.level, {0, 0, 0}, cell);
      if (!map || !map->preserves_orientation() || map->mirrored) continue;
      const GlobalBox image = map->apply(cell);
      BlockIndex K{};
      for (std::size_t e = 0; e < 3; ++e) K[e] = image.lo[e] / n[e];
      if (const auto g = old_forest.find(k.level, K); g >= 0) out.emplace_back(d, upper, g);
    }
  return out;
}

// Component c of group v of block s with one layer of zeros around its interior points, in
// `storage`: the prolongation of a group without ghosts (thorn.yaml `ghosts: 0`) reads one layer
// around the parent, and such groups never write ghosts, so that layer held zeros when they had it.
Field zero_padded(Block& s, int v, int c, const std::array<int, 3>& stagger, int dim, std::vector<double>& storage) {
  std::array<int, 3> n{1, 1, 1}, e{1, 1, 1};
  for (int d = 0; d < dim; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    n[ud] = s.n[ud] + stagger[ud];
    e[ud] = n[ud] + 2;
  }
  storage.assign(static_cast<std::size_t>(e[0]) * static_cast<std::size_t>(e[1]) * static_cast<std::size_t>(e[2]), 0.0);
  const std::ptrdiff_t sj = e[0], sk = static_cast<std::ptrdiff_t>(e[0]) * e[1];
  const Field p{storage.data() + (dim > 0 ? 1 : 0) + (dim > 1 ? sj : 0) + (dim > 2 ? sk : 0), sj, sk};
  const Field f = s.field(v, c);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) p(i, j, k) = f(i, j, k);
  return p;
}

Origin origin_of(const Forest& old_forest, const BlockKey& k) {
  const int dim = old_forest.dimension();
  if (const auto g = old_forest.find(k.level, k.index); g >= 0) return {Source::same, {g}};
  if (k.level > 0) {
    BlockIndex p = k.index;
    for (int d = 0; d < dim; ++d) p[static_cast<std::size_t>(d)] /= 2;
    if (const auto g = old_forest.find(k.level - 1, p); g >= 0) return {Source::parent, {g}};
  }
  Origin o{Source::children, {}};
  const int cz = dim >= 3 ? 2 : 1, cy = dim >= 2 ? 2 : 1;
  for (int c2 = 0; c2 < cz; ++c2)
    for (int c1 = 0; c1 < cy; ++c1)
      for (int c0 = 0; c0 < 2; ++c0) {
        const int c[3] = {c0, c1, c2};
        BlockIndex ch = k.index;
        for (int d = 0; d < dim; ++d) ch[static_cast<std::size_t>(d)] = 2 * k.index[static_cast<std::size_t>(d)] + c[d];
        const auto g = old_forest.find(k.level + 1, ch);
        if (g < 0) throw RunError("Grid: regrid: a new block has no source on the old mesh (more than one level apart)");
        o.old_gids.push_back(g);
      }
  return o;
}

std::size_t block_doubles(const Block& b, const VariableRegistry& vars) {
  std::size_t n = 0;
  for (int g = 0; g < vars.size(); ++g) n += b.size(g);
  return n;
}

Range origin_points(const Forest& f, const BlockKey& k) {
  Range o{};
  for (std::size_t d = 0; d < 3; ++d) o[d] = k.index[d] * f.block_cells()[d];
  return o;
}

}  // namespace

std::vector<std::unique_ptr<Block>> migrate_blocks(const Forest& old_forest, std::span<Block* const> old_blocks,
                                                   const Forest& new_forest, const BlockFactory& make_new,
                                                   const BlockFactory& make_scratch, const VariableRegistry& vars,
                                                   const LevelGeometry& geometry, const BoundaryMaps& maps,
                                                   std::span<const FaceVector> face_vectors, int rank, MPI_Comm comm,
                                                   std::vector<std::unique_ptr<Block>>* owned_old) {
  const std::vector<int> member = face_vector_membership({face_vectors.begin(), face_vectors.end()}, vars.size());
  const std::int64_t old_first = old_forest.first_gid(rank), old_count = old_forest.block_count(rank);
  const std::int64_t new_first = new_forest.first_gid(rank), new_count = new_forest.block_count(rank);
  auto old_mine = [&](std::int64_t g) { return g >= old_first && g < old_first + old_count; };

  // Who needs which old block: (old gid) per destination rank, and per source rank for mine.
  std::map<int, std::set<std::int64_t>> to_send, to_receive;
  std::vector<Origin> origins;
  for (std::int64_t g = 0; g < new_forest.total_blocks(); ++g) {
    const int dest = new_forest.owner(g);
    Origin o = origin_of(old_forest, new_forest.key(g));
    std::vector<std::int64_t> needed = o.old_gids;
    if (o.kind == Source::parent && !face_vectors.empty()) {
      o.kept_faces = kept_face_neighbours(old_forest, maps, new_forest.key(g));
      for (const auto& kf : o.kept_faces) needed.push_back(std::get<2>(kf));
    }
    for (std::int64_t s : needed) {
      const int src = old_forest.owner(s);
      if (src == dest) continue;
      if (src == rank) to_send[dest].insert(s);
      if (dest == rank) to_receive[src].insert(s);
    }
    if (dest == rank) origins.push_back(std::move(o));
  }

  std::unique_ptr<Block> probe = make_scratch(0, BlockKey{});
  const std::size_t per_block = block_doubles(*probe, vars);
  std::vector<std::vector<double>> send_buffers, recv_buffers;
  std::vector<MPI_Request> requests;
  for (auto& [r, gids] : to_receive) {
    recv_buffers.emplace_back(gids.size() * per_block);
    requests.emplace_back();
    MPI_Irecv(recv_buffers.back().data(), static_cast<int>(recv_buffers.back().size()), MPI_DOUBLE, r, 1, comm,
              &requests.back());
  }
  for (auto& [r, gids] : to_send) {
    send_buffers.emplace_back();
    auto& buf = send_buffers.back();
    buf.reserve(gids.size() * per_block);
    for (std::int64_t g : gids) {
      Block& b = *old_blocks[static_cast<std::size_t>(g - old_first)];
      for (int v = 0; v < vars.size(); ++v) buf.insert(buf.end(), b.data(v), b.data(v) + b.size(v));
    }
    requests.emplace_back();
    MPI_Isend(buf.data(), static_cast<int>(buf.size()), MPI_DOUBLE, r, 1, comm, &requests.back());
    comm::count("regrid_migration", comm::Pattern::p2p, -1, 1, static_cast<long long>(sizeof(double) * buf.size()));
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);

  // Old blocks that arrived, as scratch blocks.
  std::map<std::int64_t, std::unique_ptr<Block>> arrived;
  std::size_t which = 0;
  for (auto& [r, gids] : to_receive) {
    const double* in = recv_buffers[which++].data();
    for (std::int64_t g : gids) {
      auto b = make_scratch(g, old_forest.key(g));
      for (int v = 0; v < vars.size(); ++v) {
        std::memcpy(b->data(v), in, b->size(v) * sizeof(double));
        in += b->size(v);
      }
      arrived.emplace(g, std::move(b));
    }
  }
  auto old_block = [&](std::int64_t g) -> Block& {
    if (old_mine(g)) return *old_blocks[static_cast<std::size_t>(g - old_first)];
    return *arrived.at(g);
  };

  std::vector<std::unique_ptr<Block>> out;
  out.reserve(static_cast<std::size_t>(new_count));
  std::vector<double> padded;  // zero_padded's storage, reused
  for (std::int64_t i = 0; i < new_count; ++i) {
    const std::int64_t gid = new_first + i;
    const BlockKey& key = new_forest.key(gid);
    const Origin& o = origins[static_cast<std::size_t>(i)];
    // An unchanged block of this rank is moved, not copied: old and new storage coexist only for
    // the blocks that change (issue 21, goal 7; the head-on run's peak was 43 old + 64 new blocks).
    // Later new blocks may still read it as an old block (kept faces): it stays alive, unchanged.
    if (o.kind == Source::same && owned_old && old_mine(o.old_gids[0])) {
      auto& kept = (*owned_old)[static_cast<std::size_t>(o.old_gids[0] - old_first)];
      kept->gid = gid;
      out.push_back(std::move(kept));
      continue;
    }
    auto nb = make_new(gid, key);
    for (int v = 0; v < vars.size(); ++v) {
      const auto& spec = vars.group(v);
      if (o.kind == Source::same) {
        Block& s = old_block(o.old_gids[0]);
        std::memcpy(nb->data(v), s.data(v), s.size(v) * sizeof(double));
        continue;
      }
      if (const int fv = member[static_cast<std::size_t>(v)]; fv >= 0 && o.kind == Source::parent) {
        // The whole vector at once, when its first group comes up.
        const FaceVector& vec = face_vectors[static_cast<std::size_t>(fv)];
        if (vec.group[0] != v) continue;
        std::vector<KeptFace> kept;
        for (const auto& [d, upper, g] : o.kept_faces) kept.push_back({d, upper, &old_block(g)});
        prolong_face_vector(old_block(o.old_gids[0]), *nb, vec, new_forest.dimension(), kept);
        continue;
      }
      const auto stagger = effective_stagger(spec.centering, new_forest.dimension());
      const GlobalBox interior = interior_box(new_forest, key, stagger);
      for (std::int64_t src_gid : o.old_gids) {
        const BlockKey& sk = old_forest.key(src_gid);
        Transfer t;
        t.kind = o.kind == Source::parent ? TransferKind::prolong : TransferKind::restrict;
        t.src_gid = src_gid;
        t.dst_gid = gid;
        t.src_level = sk.level;
        t.dst_level = key.level;
        t.src_origin = origin_points(old_forest, sk);
        t.dst_origin = origin_points(new_forest, key);
        GlobalBox part = interior;
        if (o.kind == Source::children) {
          // The part of the parent that this child covers.
          GlobalBox cover = interior_box(old_forest, sk, stagger);
          for (int d = 0; d < new_forest.dimension(); ++d) {
            const auto ud = static_cast<std::size_t>(d);
            cover.lo[ud] = cover.lo[ud] / 2;
            cover.hi[ud] = cover.lo[ud] + new_forest.block_cells()[ud] / 2 + (stagger[ud] ? 1 : 0);
          }
          part = intersect(interior, cover);
        }
        for (std::size_t d = 0; d < 3; ++d) {
          t.dst_box.lo[d] = static_cast<int>(part.lo[d] - t.dst_origin[d]);
          t.dst_box.hi[d] = static_cast<int>(part.hi[d] - t.dst_origin[d]);
        }
        Block& s = old_block(src_gid);
        const bool pad = spec.ghosts == 0 && t.kind == TransferKind::prolong;
        for (int c = 0; c < spec.ncomp(); ++c)
          apply_transfer(t, pad ? zero_padded(s, v, c, stagger, new_forest.dimension(), padded) : s.field(v, c),
                         nb->field(v, c), 1.0, stagger, new_forest.dimension(), geometry);
      }
    }
    out.push_back(std::move(nb));
  }
  return out;
}

}  // namespace remnant::grid
