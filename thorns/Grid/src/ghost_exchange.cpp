#include "ghost_exchange.hpp"

#include "ghost_plan.hpp"
#include "remnant/comm_counters.hpp"

namespace remnant::grid {

namespace {

// The sign a ghost takes from its image: coordinate-basis parity, or Cartesian for groups
// declared with `basis: cartesian`.
double component_sign(const IndexMap& map, const VariableGroupSpec& spec, int c) {
  const ComponentSpec& comp = spec.components[static_cast<std::size_t>(c)];
  return spec.cartesian_basis ? map.cartesian_parity(comp) : map.sign(comp);
}

int phase_of(const Transfer& t) { return t.kind == TransferKind::prolong ? t.dst_level : 0; }
}  // namespace

GhostExchange::GhostExchange(const Forest& forest, const BoundaryMaps& maps, const LevelGeometry& geometry,
                             std::span<Block* const> blocks, int rank, MPI_Comm comm,
                             const std::array<int, 3>& stagger, int ghost_zones)
    : comm_(comm), dimension_(forest.dimension()), stagger_(stagger), geometry_(&geometry),
      blocks_(blocks.begin(), blocks.end()), first_gid_(forest.first_gid(rank)) {
  // Every rank enumerates the transfers of the whole mesh in the same order and keeps those it
  // takes part in: both sides of a message then agree on its layout without talking.
  std::vector<Transfer> all;
  const std::int64_t mine_lo = first_gid_, mine_hi = first_gid_ + forest.block_count(rank);
  auto is_mine = [&](std::int64_t g) { return g >= mine_lo && g < mine_hi; };
  for (std::int64_t gid = 0; gid < forest.total_blocks(); ++gid) {
    all.clear();
    plan_ghost_transfers(forest, maps, gid, stagger, ghost_zones, all);
    for (const Transfer& t : all)
      if (is_mine(t.dst_gid) || is_mine(t.src_gid)) transfers_.push_back(t);
  }
  phases_.resize(static_cast<std::size_t>(forest.finest_level() + 1));
  for (const Transfer& t : transfers_) {
    Phase& ph = phases_[static_cast<std::size_t>(phase_of(t))];
    const bool dst_mine = is_mine(t.dst_gid), src_mine = is_mine(t.src_gid);
    if (dst_mine && src_mine) {
      ph.local.push_back(&t);
    } else if (dst_mine) {
      Peer& p = ph.recvs[forest.owner(t.src_gid)];
      p.rank = forest.owner(t.src_gid);
      p.transfers.push_back(&t);
      p.points += t.src_box.points();
    } else {
      Peer& p = ph.sends[forest.owner(t.dst_gid)];
      p.rank = forest.owner(t.dst_gid);
      p.transfers.push_back(&t);
      p.points += t.src_box.points();
    }
  }
}

std::size_t GhostExchange::local_transfers() const {
  std::size_t n = 0;
  for (const Phase& p : phases_) n += p.local.size();
  return n;
}

std::size_t GhostExchange::messages() const {
  std::size_t n = 0;
  for (const Phase& p : phases_) n += p.sends.size();
  return n;
}

void GhostExchange::run(const VariableRegistry& vars, std::span<const int> groups,
                        const std::function<void(int)>& after_phase) {
  if (blocks_.empty()) {
    // Still take part in the phases' collective structure (nothing to send or receive).
    for (int p = 0; p < phases(); ++p) after_phase(p);
    return;
  }
  std::vector<GroupLayout> layouts;
  std::size_t ncomp = 0;
  for (int g : groups) {
    layouts.emplace_back(*blocks_.front(), g, vars.group(g).ncomp());
    ncomp += static_cast<std::size_t>(layouts.back().ncomp);
  }
  if (ncomp == 0) return;
  std::vector<MPI_Request> requests;

  for (int phase = 0; phase < phases(); ++phase) {
    const Phase& ph = phases_[static_cast<std::size_t>(phase)];
    std::size_t send_total = 0, recv_total = 0;
    for (const auto& [r, p] : ph.sends) send_total += p.points * ncomp;
    for (const auto& [r, p] : ph.recvs) recv_total += p.points * ncomp;
    if (send_buffer_.size() < send_total) send_buffer_.resize(send_total);
    if (recv_buffer_.size() < recv_total) recv_buffer_.resize(recv_total);
    requests.assign(ph.sends.size() + ph.recvs.size(), MPI_REQUEST_NULL);
    std::size_t req = 0, offset = 0;
    // Receives first, so that no message waits in an unexpected-message queue.
    for (const auto& [r, p] : ph.recvs) {
      MPI_Irecv(recv_buffer_.data() + offset, static_cast<int>(p.points * ncomp), MPI_DOUBLE, r, phase, comm_,
                &requests[req++]);
      offset += p.points * ncomp;
    }
    offset = 0;
    for (const auto& [r, p] : ph.sends) {
      double* const start = send_buffer_.data() + offset;
      double* out = start;
      for (const Transfer* t : p.transfers) {
        Block& src = local_block(t->src_gid);
        for (const GroupLayout& gl : layouts)
          for (int c = 0; c < gl.ncomp; ++c) out = pack_box(gl.field(src, c), t->src_box, out);
      }
      MPI_Isend(start, static_cast<int>(out - start), MPI_DOUBLE, r, phase, comm_, &requests[req++]);
      offset += p.points * ncomp;
    }
    comm::count("ghost_exchange", comm::Pattern::p2p, phase, static_cast<long long>(ph.sends.size()),
                static_cast<long long>(sizeof(double) * send_total), static_cast<long long>(send_total / ncomp));

    // Local transfers overlap with the messages in flight.
    for (const Transfer* t : ph.local) {
      Block& src = local_block(t->src_gid);
      Block& dst = local_block(t->dst_gid);
      for (const GroupLayout& gl : layouts) {
        const auto& spec = vars.group(gl.group);
        for (int c = 0; c < gl.ncomp; ++c)
          apply_transfer(*t, gl.field(src, c), gl.field(dst, c), component_sign(t->map, spec, c),
                         stagger_, dimension_, *geometry_);
      }
    }

    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    offset = 0;
    for (const auto& [r, p] : ph.recvs) {
      double* in = recv_buffer_.data() + offset;
      for (const Transfer* t : p.transfers) {
        Block& dst = local_block(t->dst_gid);
        const std::size_t points = t->src_box.points();
        for (const GroupLayout& gl : layouts) {
          const auto& spec = vars.group(gl.group);
          for (int c = 0; c < gl.ncomp; ++c) {
            apply_transfer(*t, buffer_field(in, t->src_box), gl.field(dst, c),
                           component_sign(t->map, spec, c), stagger_, dimension_, *geometry_);
            in += points;
          }
        }
      }
      offset += p.points * ncomp;
    }
    after_phase(phase);
  }
}

}  // namespace remnant::grid
