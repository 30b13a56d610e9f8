#include "edge_correction.hpp"

#include <string>

#include "remnant/error.hpp"

namespace remnant::grid {

EdgeCorrection::EdgeCorrection(const Forest& forest, const BoundaryMaps& maps, std::span<Block* const> blocks,
                               int rank, MPI_Comm comm, const std::array<int, 3>& stagger)
    : comm_(comm), dimension_(forest.dimension()), stagger_(stagger), blocks_(blocks.begin(), blocks.end()),
      first_gid_(forest.first_gid(rank)) {
  const auto& n = forest.block_cells();
  const int dim = dimension_;
  const std::int64_t mine_lo = first_gid_, mine_hi = first_gid_ + forest.block_count(rank);
  auto is_mine = [&](std::int64_t g) { return g >= mine_lo && g < mine_hi; };
  // Enumerated over the whole mesh in gid order, so that both sides agree on message layouts.
  for (std::int64_t gid = 0; gid < forest.total_blocks(); ++gid) {
    const BlockKey& ck = forest.key(gid);
    const int l = ck.level;
    if (l >= forest.finest_level()) continue;
    Range origin{};
    for (std::size_t e = 0; e < 3; ++e) origin[e] = ck.index[e] * n[e];
    for (const Offset& o : neighbour_offsets(dim)) {
      // Edges lie on the boundary towards o only if they sit on nodes in every direction of o.
      bool on_boundary = true;
      for (int d = 0; d < dim; ++d) on_boundary &= o[static_cast<std::size_t>(d)] == 0 || stagger_[static_cast<std::size_t>(d)] == 1;
      if (!on_boundary) continue;
      GlobalBox cell, points;
      for (std::size_t e = 0; e < 3; ++e) {
        const bool used = static_cast<int>(e) < dim;
        const int oe = o[e];
        cell.lo[e] = oe < 0 ? origin[e] - 1 : (oe > 0 ? origin[e] + n[e] : origin[e]);
        cell.hi[e] = oe == 0 ? origin[e] + (used ? n[e] : 1) : cell.lo[e] + 1;
        points.lo[e] = oe > 0 ? origin[e] + n[e] : origin[e];
        points.hi[e] = oe == 0 ? origin[e] + (used ? n[e] + stagger_[e] : 1) : points.lo[e] + 1;
      }
      const auto map = maps.image(l, {0, 0, 0}, cell);
      if (!map || !map->preserves_orientation() || map->mirrored) continue;
      const GlobalBox image = map->apply(cell);
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
            BlockIndex Kf = K;
            GlobalBox cover;  // the child's points, in level-l indices of the image frame
            for (std::size_t e = 0; e < 3; ++e) {
              if (static_cast<int>(e) >= dim) continue;
              Kf[e] = 2 * K[e] + c[e];
              cover.lo[e] = Kf[e] * n[e] / 2;
              cover.hi[e] = cover.lo[e] + n[e] / 2 + stagger_[e];
            }
            const GlobalBox part = intersect(point_image, cover);
            if (part.empty()) continue;
            const std::int64_t fine = forest.find(l + 1, Kf);
            if (fine < 0) throw RunError("Grid: internal error: correct_edges found no fine leaf (mesh not 2:1 balanced)");
            if (!is_mine(fine) && !is_mine(gid)) continue;
            Item it;
            it.fine_gid = fine;
            it.coarse_gid = gid;
            for (std::size_t e = 0; e < 3; ++e) {
              it.coarse_points.lo[e] = static_cast<int>(part.lo[e] - map->shift[e] - origin[e]);
              it.coarse_points.hi[e] = static_cast<int>(part.hi[e] - map->shift[e] - origin[e]);
              if (static_cast<int>(e) < dim)
                it.fine_shift[e] = static_cast<int>(2 * (origin[e] + map->shift[e]) - Kf[e] * n[e]);
            }
            items_.push_back(it);
          }
    }
  }
  for (const Item& it : items_) {
    const bool fine_mine = is_mine(it.fine_gid), coarse_mine = is_mine(it.coarse_gid);
    if (fine_mine && coarse_mine) local_.push_back(&it);
    else if (fine_mine) {
      Peer& p = sends_[forest.owner(it.coarse_gid)];
      p.items.push_back(&it);
      p.values += it.coarse_points.points();
    } else {
      Peer& p = recvs_[forest.owner(it.fine_gid)];
      p.items.push_back(&it);
      p.values += it.coarse_points.points();
    }
  }
}

// The mean of the two fine edges along each coarse edge (one value along an unused direction).
void EdgeCorrection::fine_means(const Item& it, const Field& f, double* out) const {
  const Box& b = it.coarse_points;
  int along = -1;
  for (int e = 0; e < dimension_; ++e)
    if (!stagger_[static_cast<std::size_t>(e)]) along = e;
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j)
      for (int i = b.lo[0]; i < b.hi[0]; ++i) {
        int p[3] = {i, j, k};
        for (int e = 0; e < dimension_; ++e) p[e] = 2 * p[e] + it.fine_shift[static_cast<std::size_t>(e)];
        double v = f(p[0], p[1], p[2]);
        if (along >= 0) {
          p[along] += 1;
          v = 0.5 * (v + f(p[0], p[1], p[2]));
        }
        *out++ = v;
      }
}

void EdgeCorrection::coarse_update(const Item& it, const Field& f, const double* in) {
  const Box& b = it.coarse_points;
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j)
      for (int i = b.lo[0]; i < b.hi[0]; ++i) f(i, j, k) = *in++;
}

void EdgeCorrection::run(const VariableRegistry& vars, std::span<const int> edge_groups) {
  std::size_t ncomp = 0;
  for (int g : edge_groups) ncomp += static_cast<std::size_t>(vars.group(g).ncomp());
  auto pack = [&](const Item& it, double* out) {
    Block& fine = local_block(it.fine_gid);
    for (int g : edge_groups)
      for (int comp = 0; comp < vars.group(g).ncomp(); ++comp) {
        fine_means(it, fine.field(g, comp), out);
        out += it.coarse_points.points();
      }
    return out;
  };
  auto unpack = [&](const Item& it, const double* in) {
    Block& coarse = local_block(it.coarse_gid);
    for (int g : edge_groups)
      for (int comp = 0; comp < vars.group(g).ncomp(); ++comp) {
        coarse_update(it, coarse.field(g, comp), in);
        in += it.coarse_points.points();
      }
    return in;
  };
  std::size_t send_total = 0, recv_total = 0;
  for (auto& [r, p] : sends_) send_total += p.values * ncomp;
  for (auto& [r, p] : recvs_) recv_total += p.values * ncomp;
  send_buffer_.resize(send_total);
  recv_buffer_.resize(recv_total);
  std::vector<MPI_Request> requests;
  double* in = recv_buffer_.data();
  for (auto& [r, p] : recvs_) {
    requests.emplace_back();
    MPI_Irecv(in, static_cast<int>(p.values * ncomp), MPI_DOUBLE, r, 2, comm_, &requests.back());
    in += p.values * ncomp;
  }
  double* out = send_buffer_.data();
  for (auto& [r, p] : sends_) {
    double* start = out;
    for (const Item* it : p.items) out = pack(*it, out);
    requests.emplace_back();
    MPI_Isend(start, static_cast<int>(out - start), MPI_DOUBLE, r, 2, comm_, &requests.back());
  }
  for (const Item* it : local_) {
    scratch_.resize(it->coarse_points.points() * ncomp);
    pack(*it, scratch_.data());
    unpack(*it, scratch_.data());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  const double* pos = recv_buffer_.data();
  for (auto& [r, p] : recvs_)
    for (const Item* it : p.items) pos = unpack(*it, pos);
}

}  // namespace remnant::grid
