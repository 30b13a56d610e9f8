#pragma once
// Filling ghost zones of cell-centred groups from the neighbouring blocks (faces, edges and
// corners): local neighbours by direct copies, remote ones by non-blocking messages, one per
// (receiving block, direction). The plan is built once; synchronisations only move data.
#include <mpi.h>

#include <span>
#include <vector>

#include "block_layout.hpp"
#include "box.hpp"

namespace remnant::grid {

class GhostExchange {
 public:
  // `blocks` are this rank's blocks, in gid order.
  GhostExchange(const BlockLayout& layout, std::span<Block* const> blocks, int rank, MPI_Comm comm);

  // All groups must be cell-centred (checked by the caller). Collective over the communicator.
  void run(const VariableRegistry& vars, std::span<const int> groups);

  std::size_t local_copies() const { return local_.size(); }
  std::size_t messages() const { return sends_.size(); }

 private:
  struct LocalCopy {
    Block* src;
    Box from;
    Block* dst;
    Box to;
  };
  struct Message {
    Block* block;             // the sender's source block or the receiver's destination block
    Box box;
    int peer;
    int tag;
    std::size_t first_point;  // offset in the buffer, in points of one component
  };

  MPI_Comm comm_;
  std::vector<Block*> blocks_;  // all of one shape, as on a uniform grid or in a block forest
  std::vector<LocalCopy> local_;
  std::vector<Message> sends_, recvs_;
  std::size_t send_points_ = 0, recv_points_ = 0;
  std::vector<double> send_buffer_, recv_buffer_;
  std::vector<MPI_Request> requests_;
};

}  // namespace remnant::grid
