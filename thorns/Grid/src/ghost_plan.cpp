#include "ghost_plan.hpp"

#include <string>

#include "remnant/error.hpp"

namespace remnant::grid {

namespace {

std::int64_t floor_div(std::int64_t a, std::int64_t b) { return a >= 0 ? a / b : -((b - 1 - a) / b); }

Box to_local(const GlobalBox& g, const Range& origin) {
  Box b;
  for (std::size_t d = 0; d < 3; ++d) {
    b.lo[d] = static_cast<int>(g.lo[d] - origin[d]);
    b.hi[d] = static_cast<int>(g.hi[d] - origin[d]);
  }
  return b;
}

}  // namespace

GlobalBox interior_box(const Forest& forest, const BlockKey& key, const std::array<int, 3>& stagger) {
  GlobalBox g;
  const Range o = forest.origin(key);
  for (std::size_t d = 0; d < 3; ++d) {
    const bool used = static_cast<int>(d) < forest.dimension();
    g.lo[d] = o[d];
    g.hi[d] = o[d] + forest.block_cells()[d] + (used ? stagger[d] : 0);
  }
  return g;
}

void plan_ghost_transfers(const Forest& forest, const BoundaryMaps& maps, std::int64_t gid,
                          const std::array<int, 3>& stagger_in, int ng, std::vector<Transfer>& out) {
  const BlockKey& key = forest.key(gid);
  const int dim = forest.dimension();
  const int l = key.level;
  const auto& n = forest.block_cells();
  std::array<int, 3> stagger{};
  for (int d = 0; d < dim; ++d) stagger[static_cast<std::size_t>(d)] = stagger_in[static_cast<std::size_t>(d)];
  const Range dst_origin = forest.origin(key);
  const BlockIndex nb = forest.blocks_on_level(l);

  for (const Offset& o : neighbour_offsets(dim)) {
    // The ghost box in global indices of level l.
    GlobalBox ghost;
    for (std::size_t d = 0; d < 3; ++d) {
      const int lo = o[d] < 0 ? -ng : (o[d] == 0 ? 0 : n[d] + stagger[d]);
      const int hi = o[d] < 0 ? 0 : (o[d] == 0 ? n[d] + stagger[d] : n[d] + stagger[d] + ng);
      ghost.lo[d] = dst_origin[d] + (static_cast<int>(d) < dim ? lo : 0);
      ghost.hi[d] = dst_origin[d] + (static_cast<int>(d) < dim ? hi : 1);
    }
    const auto map = maps.image(l, stagger, ghost);
    if (!map) continue;
    const GlobalBox image = map->apply(ghost);
    // The level-l block whose range holds the image (faces on a block's upper face belong to it too).
    BlockIndex K{};
    for (std::size_t d = 0; d < 3; ++d) {
      K[d] = floor_div(image.lo[d], n[d]);
      if (K[d] >= nb[d]) K[d] = nb[d] - 1;
    }
    auto add = [&](TransferKind kind, std::int64_t src, const GlobalBox& part_image) {
      const BlockKey& sk = forest.key(src);
      Transfer t;
      t.kind = kind;
      t.src_gid = src;
      t.dst_gid = gid;
      t.src_level = sk.level;
      t.dst_level = l;
      t.src_origin = forest.origin(sk);
      t.dst_origin = dst_origin;
      t.map = *map;
      t.dst_box = to_local(map->inverse(part_image), dst_origin);
      // What the kernel reads, on the source level.
      GlobalBox s = part_image;
      for (int d = 0; d < dim; ++d) {
        const auto ud = static_cast<std::size_t>(d);
        if (kind == TransferKind::restrict) {
          s.lo[ud] = 2 * part_image.lo[ud];
          s.hi[ud] = stagger[ud] ? 2 * (part_image.hi[ud] - 1) + 1 : 2 * part_image.hi[ud];
        } else if (kind == TransferKind::prolong) {
          const bool cells = stagger[0] + stagger[1] + stagger[2] == 0;
          s.lo[ud] = floor_div(part_image.lo[ud], 2) - (cells ? 1 : 0);
          s.hi[ud] = floor_div(part_image.hi[ud] - 1, 2) + 1 + (cells || stagger[ud] ? 1 : 0);
        }
      }
      t.src_box = to_local(s, t.src_origin);
      out.push_back(t);
    };
    if (const std::int64_t same = forest.find(l, K); same >= 0) {
      add(TransferKind::copy, same, image);
      continue;
    }
    BlockIndex Kc = K;
    for (int d = 0; d < dim; ++d) Kc[static_cast<std::size_t>(d)] = K[static_cast<std::size_t>(d)] / 2;
    if (l > 0) {
      if (const std::int64_t coarse = forest.find(l - 1, Kc); coarse >= 0) {
        add(TransferKind::prolong, coarse, image);
        continue;
      }
    }
    // Finer children of K: each covers half of K's range per direction.
    const int cz = dim >= 3 ? 2 : 1, cy = dim >= 2 ? 2 : 1;
    for (int c2 = 0; c2 < cz; ++c2)
      for (int c1 = 0; c1 < cy; ++c1)
        for (int c0 = 0; c0 < 2; ++c0) {
          const int c[3] = {c0, c1, c2};
          const auto [Kf, cover] = forest.child_cover(K, c, stagger);
          const GlobalBox part = intersect(image, cover);
          if (part.empty()) continue;
          const std::int64_t fine = forest.find(l + 1, Kf);
          if (fine < 0)
            throw RunError("Grid: internal error: no leaf covers the ghosts of block " + std::to_string(gid) +
                           " (level " + std::to_string(l) + ", index " + std::to_string(key.index[0]) + " " +
                           std::to_string(key.index[1]) + " " + std::to_string(key.index[2]) + ", offset " +
                           std::to_string(o[0]) + " " + std::to_string(o[1]) + " " + std::to_string(o[2]) +
                           "): the mesh is not 2:1 balanced");
          add(TransferKind::restrict, fine, part);
        }
  }
}

}  // namespace remnant::grid
