#include "ghost_exchange.hpp"

#include <string>
#include <vector>

#include "remnant/error.hpp"

namespace remnant::grid {

namespace {

// The ghost box of `b` that its neighbour in direction `o` fills.
Box ghost_box(const Block& b, const Offset& o) {
  Box box;
  for (std::size_t d = 0; d < 3; ++d) {
    const int n = b.n[d], ng = b.ng[d];
    box.lo[d] = o[d] < 0 ? -ng : (o[d] == 0 ? 0 : n);
    box.hi[d] = o[d] < 0 ? 0 : (o[d] == 0 ? n : n + ng);
  }
  return box;
}

// The interior box of `b` that its neighbour in direction `o` needs for its ghosts.
Box source_box(const Block& b, const Offset& o) {
  Box box;
  for (std::size_t d = 0; d < 3; ++d) {
    const int n = b.n[d], ng = b.ng[d];
    box.lo[d] = o[d] > 0 ? n - ng : 0;
    box.hi[d] = o[d] < 0 ? ng : n;
  }
  return box;
}

Offset opposite(const Offset& o) { return {-o[0], -o[1], -o[2]}; }

// Unique per (receiving block, direction it receives from).
int message_tag(std::int64_t receiver_gid, const Offset& from) {
  return static_cast<int>(receiver_gid * 27 + offset_code(from));
}

}  // namespace

GhostExchange::GhostExchange(const BlockLayout& layout, std::span<Block* const> blocks, int rank,
                             MPI_Comm comm)
    : comm_(comm), blocks_(blocks.begin(), blocks.end()) {
  int* tag_ub = nullptr;
  int flag = 0;
  MPI_Comm_get_attr(comm, MPI_TAG_UB, &tag_ub, &flag);
  const std::int64_t max_tag = layout.total_blocks() * 27 - 1;
  if (flag && max_tag > *tag_ub)
    throw RunError("Grid: " + std::to_string(layout.total_blocks()) +
                   " blocks need message tags up to " + std::to_string(max_tag) +
                   ", above this MPI's limit " + std::to_string(*tag_ub) + "; use larger blocks");

  const std::int64_t first = layout.first_gid(rank);
  auto local_block = [&](std::int64_t gid) { return blocks[static_cast<std::size_t>(gid - first)]; };
  const auto offsets = neighbour_offsets(layout.dimension());
  for (Block* b : blocks) {
    for (const Offset& o : offsets) {
      const std::int64_t ngid = layout.neighbour(b->gid, o);
      if (ngid < 0) continue;  // a domain face: the outer boundary condition fills it
      const int peer = layout.owner(ngid);
      if (peer == rank) {
        Block* nb = local_block(ngid);
        local_.push_back({nb, source_box(*nb, opposite(o)), b, ghost_box(*b, o)});
        continue;
      }
      // The neighbour relation is symmetric, so every remote pair sends once each way.
      const Box to = ghost_box(*b, o);
      recvs_.push_back({b, to, peer, message_tag(b->gid, o), recv_points_});
      recv_points_ += to.points();
      const Box from = source_box(*b, o);
      sends_.push_back({b, from, peer, message_tag(ngid, opposite(o)), send_points_});
      send_points_ += from.points();
    }
  }
}

void GhostExchange::run(const VariableRegistry& vars, std::span<const int> groups) {
  if (blocks_.empty()) return;
  std::vector<GroupLayout> layouts;
  std::size_t ncomp = 0;
  for (int g : groups) {
    layouts.emplace_back(*blocks_.front(), g, vars.group(g).ncomp());
    ncomp += static_cast<std::size_t>(layouts.back().ncomp);
  }
  if (ncomp == 0) return;
  if (send_buffer_.size() < send_points_ * ncomp) send_buffer_.resize(send_points_ * ncomp);
  if (recv_buffer_.size() < recv_points_ * ncomp) recv_buffer_.resize(recv_points_ * ncomp);
  requests_.assign(recvs_.size() + sends_.size(), MPI_REQUEST_NULL);

  // Receives first, so that no message waits in an unexpected-message queue.
  std::size_t r = 0;
  for (const Message& m : recvs_)
    MPI_Irecv(recv_buffer_.data() + m.first_point * ncomp, static_cast<int>(m.box.points() * ncomp),
              MPI_DOUBLE, m.peer, m.tag, comm_, &requests_[r++]);
  for (const Message& m : sends_) {
    double* const start = send_buffer_.data() + m.first_point * ncomp;
    double* out = start;
    for (const GroupLayout& gl : layouts)
      for (int c = 0; c < gl.ncomp; ++c) out = pack_box(gl.field(*m.block, c), m.box, out);
    MPI_Isend(start, static_cast<int>(out - start), MPI_DOUBLE, m.peer, m.tag, comm_, &requests_[r++]);
  }

  // Local copies overlap with the messages in flight.
  for (const LocalCopy& lc : local_)
    for (const GroupLayout& gl : layouts)
      for (int c = 0; c < gl.ncomp; ++c) copy_box(gl.field(*lc.src, c), lc.from, gl.field(*lc.dst, c), lc.to);

  MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
  for (const Message& m : recvs_) {
    const double* in = recv_buffer_.data() + m.first_point * ncomp;
    for (const GroupLayout& gl : layouts)
      for (int c = 0; c < gl.ncomp; ++c) in = unpack_box(in, gl.field(*m.block, c), m.box);
  }
}

}  // namespace remnant::grid
