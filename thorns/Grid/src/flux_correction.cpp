#include "flux_correction.hpp"

#include <string>

#include "remnant/comm_counters.hpp"
#include "remnant/error.hpp"

namespace remnant::grid {

FluxCorrection::FluxCorrection(const Forest& forest, const BoundaryMaps& maps, std::span<Block* const> blocks,
                               int rank, MPI_Comm comm)
    : comm_(comm), dimension_(forest.dimension()), blocks_(blocks.begin(), blocks.end()),
      first_gid_(forest.first_gid(rank)) {
  const auto& n = forest.block_cells();
  const std::int64_t mine_lo = first_gid_, mine_hi = first_gid_ + forest.block_count(rank);
  auto is_mine = [&](std::int64_t g) { return g >= mine_lo && g < mine_hi; };
  // Enumerated over the whole mesh in gid order, so that both sides agree on message layouts.
  for (std::int64_t gid = 0; gid < forest.total_blocks(); ++gid) {
    const BlockKey& ck = forest.key(gid);
    const int l = ck.level;
    if (l >= forest.finest_level()) continue;
    for (int d = 0; d < dimension_; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      for (const bool upper : {false, true}) {
        // The neighbouring level-l block across this face, through periodic faces only (a
        // mirror face is the block's own face).
        GlobalBox cell;
        for (std::size_t e = 0; e < 3; ++e) {
          cell.lo[e] = ck.index[e] * n[e];
          cell.hi[e] = cell.lo[e] + 1;
        }
        cell.lo[ud] = upper ? (ck.index[ud] + 1) * n[ud] : ck.index[ud] * n[ud] - 1;
        cell.hi[ud] = cell.lo[ud] + 1;
        const auto map = maps.image(l, {0, 0, 0}, cell);
        if (!map || !map->preserves_orientation() || map->mirrored) continue;
        const GlobalBox image = map->apply(cell);
        BlockIndex K{};
        for (std::size_t e = 0; e < 3; ++e) K[e] = image.lo[e] / n[e];
        if (forest.find(l, K) >= 0) continue;
        BlockIndex Kc = K;
        for (int e = 0; e < dimension_; ++e) Kc[static_cast<std::size_t>(e)] /= 2;
        if (l > 0 && forest.find(l - 1, Kc) >= 0) continue;
        // Finer: the children of K that touch this face.
        const int cz = dimension_ >= 3 ? 2 : 1, cy = dimension_ >= 2 ? 2 : 1;
        for (int c2 = 0; c2 < cz; ++c2)
          for (int c1 = 0; c1 < cy; ++c1)
            for (int c0 = 0; c0 < 2; ++c0) {
              const int c[3] = {c0, c1, c2};
              if (c[d] != (upper ? 0 : 1)) continue;
              BlockIndex Kf = K;
              for (int e = 0; e < dimension_; ++e) Kf[static_cast<std::size_t>(e)] = 2 * K[static_cast<std::size_t>(e)] + c[e];
              const std::int64_t fine = forest.find(l + 1, Kf);
              if (fine < 0) throw RunError("Grid: internal error: refluxing found no fine leaf (mesh not 2:1 balanced)");
              if (!is_mine(fine) && !is_mine(gid)) continue;
              Item it;
              it.direction = d;
              it.fine_gid = fine;
              it.coarse_gid = gid;
              it.fine_face = upper ? 0 : n[ud];
              it.coarse_face = upper ? n[ud] : 0;
              for (std::size_t e = 0; e < 3; ++e) {
                if (static_cast<int>(e) == d || static_cast<int>(e) >= dimension_) {
                  it.coarse_tangential.lo[e] = 0;
                  it.coarse_tangential.hi[e] = 1;
                  continue;
                }
                // The half of the coarse block's tangential range that child c covers.
                const std::int64_t child_lo = Kf[e] * n[e] / 2;  // on level l, in the image frame
                const std::int64_t shift = map->shift[e];
                const int lo = static_cast<int>(child_lo - shift - ck.index[e] * n[e]);
                it.coarse_tangential.lo[e] = lo;
                it.coarse_tangential.hi[e] = lo + n[e] / 2;
                it.fine_offset[e] = static_cast<int>(2 * (ck.index[e] * n[e] + shift) - Kf[e] * n[e]);
              }
              items_.push_back(it);
            }
      }
    }
  }
  for (const Item& it : items_) {
    const bool fine_mine = is_mine(it.fine_gid), coarse_mine = is_mine(it.coarse_gid);
    if (fine_mine && coarse_mine) local_.push_back(&it);
    else if (fine_mine) {
      Peer& p = sends_[forest.owner(it.coarse_gid)];
      p.items.push_back(&it);
      p.values += it.values();
    } else {
      Peer& p = recvs_[forest.owner(it.fine_gid)];
      p.items.push_back(&it);
      p.values += it.values();
    }
  }
}

// Sum over the fine faces of each coarse face of flux * tangential weight, in a fixed order.
void FluxCorrection::fine_sums(const Item& it, Block& fine, const Field& flux, double* out) const {
  const Box& t = it.coarse_tangential;
  const int d = it.direction;
  const int nchild[3] = {d == 0 || dimension_ < 1 ? 1 : 2, d == 1 || dimension_ < 2 ? 1 : 2, d == 2 || dimension_ < 3 ? 1 : 2};
  for (int k = t.lo[2]; k < t.hi[2]; ++k)
    for (int j = t.lo[1]; j < t.hi[1]; ++j)
      for (int i = t.lo[0]; i < t.hi[0]; ++i) {
        const int c[3] = {i, j, k};
        double s = 0;
        for (int b2 = 0; b2 < nchild[2]; ++b2)
          for (int b1 = 0; b1 < nchild[1]; ++b1)
            for (int b0 = 0; b0 < nchild[0]; ++b0) {
              const int b[3] = {b0, b1, b2};
              int f[3];
              double w = 1;
              for (int e = 0; e < 3; ++e) {
                if (e == d) {
                  f[e] = it.fine_face;
                } else if (e < dimension_) {
                  f[e] = 2 * c[e] + it.fine_offset[static_cast<std::size_t>(e)] + b[e];
                  w *= fine.volume_weight(e, f[e]);
                } else {
                  f[e] = 0;
                }
              }
              s += w * flux(f[0], f[1], f[2]);
            }
        *out++ = s;
      }
}

void FluxCorrection::coarse_update(const Item& it, Block& coarse, const Field& flux, const double* in) const {
  const Box& t = it.coarse_tangential;
  const int d = it.direction;
  for (int k = t.lo[2]; k < t.hi[2]; ++k)
    for (int j = t.lo[1]; j < t.hi[1]; ++j)
      for (int i = t.lo[0]; i < t.hi[0]; ++i) {
        int c[3] = {i, j, k};
        double w = 1;
        for (int e = 0; e < dimension_; ++e)
          if (e != d) w *= coarse.volume_weight(e, c[e]);
        c[d] = it.coarse_face;
        flux(c[0], c[1], c[2]) = *in++ / w;
      }
}

void FluxCorrection::run(const VariableRegistry& vars, std::span<const int> face_groups) {
  for (int g : face_groups) {
    const auto c = vars.group(g).centering;
    if (c != Centering::face_x && c != Centering::face_y && c != Centering::face_z)
      throw RunError("Grid::correct_fluxes: group '" + vars.group(g).full_name() + "' is " + to_string(c) +
                     "-centred; fluxes live on faces (face_x, face_y or face_z)");
  }
  auto direction_of = [&](int g) {
    const auto s = staggering(vars.group(g).centering);
    return s[0] ? 0 : s[1] ? 1 : 2;
  };
  // Values per item: its coarse faces times the components of the groups in its direction.
  auto item_values = [&](const Item& it) {
    std::size_t n = 0;
    for (int g : face_groups)
      if (direction_of(g) == it.direction) n += it.values() * static_cast<std::size_t>(vars.group(g).ncomp());
    return n;
  };
  auto pack = [&](const Item& it, double* out) {
    Block& fine = local_block(it.fine_gid);
    for (int g : face_groups)
      if (direction_of(g) == it.direction)
        for (int comp = 0; comp < vars.group(g).ncomp(); ++comp) {
          fine_sums(it, fine, fine.field(g, comp), out);
          out += it.values();
        }
    return out;
  };
  auto unpack = [&](const Item& it, const double* in) {
    Block& coarse = local_block(it.coarse_gid);
    for (int g : face_groups)
      if (direction_of(g) == it.direction)
        for (int comp = 0; comp < vars.group(g).ncomp(); ++comp) {
          coarse_update(it, coarse, coarse.field(g, comp), in);
          in += it.values();
        }
    return in;
  };
  std::size_t send_total = 0, recv_total = 0;
  for (auto& [r, p] : sends_)
    for (const Item* it : p.items) send_total += item_values(*it);
  for (auto& [r, p] : recvs_)
    for (const Item* it : p.items) recv_total += item_values(*it);
  send_buffer_.resize(send_total);
  recv_buffer_.resize(recv_total);
  std::vector<MPI_Request> requests;
  double* in = recv_buffer_.data();
  for (auto& [r, p] : recvs_) {
    std::size_t count = 0;
    for (const Item* it : p.items) count += item_values(*it);
    requests.emplace_back();
    MPI_Irecv(in, static_cast<int>(count), MPI_DOUBLE, r, 0, comm_, &requests.back());
    in += count;
  }
  double* out = send_buffer_.data();
  for (auto& [r, p] : sends_) {
    double* start = out;
    for (const Item* it : p.items) out = pack(*it, out);
    requests.emplace_back();
    MPI_Isend(start, static_cast<int>(out - start), MPI_DOUBLE, r, 0, comm_, &requests.back());
  }
  comm::count("flux_correction", comm::Pattern::p2p, -1, static_cast<long long>(sends_.size()),
              static_cast<long long>(sizeof(double) * send_total));
  for (const Item* it : local_) {
    scratch_.resize(item_values(*it));
    pack(*it, scratch_.data());
    unpack(*it, scratch_.data());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  const double* pos = recv_buffer_.data();
  for (auto& [r, p] : recvs_)
    for (const Item* it : p.items) pos = unpack(*it, pos);
}

}  // namespace remnant::grid
