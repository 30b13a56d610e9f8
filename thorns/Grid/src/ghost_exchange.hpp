#pragma once
// Filling ghost zones from the neighbouring blocks in phases: phase 0 copies from same-level
// neighbours and restricts from finer ones; phase p (1..finest level) prolongs from coarser
// neighbours into the blocks of level p, whose coarse sources are complete by then. After each
// phase the caller applies the outflow conditions to the blocks just filled. Local transfers
// are direct; remote ones travel in one message per (peer, phase). The plan is built once per
// mesh and centering; synchronisations only move data.
#include <mpi.h>

#include <functional>
#include <map>
#include <span>
#include <vector>

#include "forest.hpp"
#include "level_geometry.hpp"
#include "transfer.hpp"

namespace remnant::grid {

class GhostExchange {
 public:
  // `blocks` are this rank's blocks in gid order (forest.first_gid(rank) onwards).
  GhostExchange(const Forest& forest, const BoundaryMaps& maps, const LevelGeometry& geometry,
                std::span<Block* const> blocks, int rank, MPI_Comm comm, const std::array<int, 3>& stagger,
                int ghost_zones);

  int phases() const { return static_cast<int>(phases_.size()); }
  // Collective. `after_phase(p)` runs after phase p on this rank.
  void run(const VariableRegistry& vars, std::span<const int> groups, const std::function<void(int)>& after_phase);

  std::size_t local_transfers() const;
  std::size_t messages() const;

 private:
  struct Peer {
    int rank = -1;
    std::vector<const Transfer*> transfers;  // in the global enumeration order
    std::size_t points = 0;                  // source points per component, summed
  };
  struct Phase {
    std::vector<const Transfer*> local;
    std::map<int, Peer> sends, recvs;
  };
  Block& local_block(std::int64_t gid) const { return *blocks_[static_cast<std::size_t>(gid - first_gid_)]; }

  MPI_Comm comm_;
  int dimension_;
  std::array<int, 3> stagger_;
  const LevelGeometry* geometry_;
  std::vector<Block*> blocks_;
  std::int64_t first_gid_ = 0;
  std::vector<Transfer> transfers_;
  std::vector<Phase> phases_;
  std::vector<double> send_buffer_, recv_buffer_;
};

}  // namespace remnant::grid
