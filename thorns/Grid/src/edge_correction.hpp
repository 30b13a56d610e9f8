#pragma once
// correct_edges, the constrained-transport analogue of refluxing, in two passes:
//  1. copies of an edge shared by blocks of the same level (across faces, edges, corners and
//     periodic faces) all take the value of the block with the lowest gid among them: blocks
//     compute their boundary EMFs from different ghosts (near refinement boundaries), and one
//     value per edge keeps their copies of the shared faces identical;
//  2. every coarse copy of an edge that is also an edge of finer blocks (on the boundary of a
//     finer region, reached through a face, an edge or a corner) takes the mean of the two fine
//     edges along it (the coincident fine value along an unused direction).
// EMFs are covariant components, so an edge's line integral is its value times its coordinate
// length and the two fine halves weigh the same. Afterwards a CT update keeps the coarse flux
// through a coarse/fine interface equal to the sum of the fine ones. One message per peer and
// pass; the plan is built once per mesh and staggering. Across mirror maps (reflect, axis,
// origin) nothing is exchanged.
#include <mpi.h>

#include <map>
#include <span>
#include <vector>

#include "boundary_map.hpp"
#include "box.hpp"
#include "forest.hpp"

namespace remnant::grid {

class EdgeCorrection {
 public:
  EdgeCorrection(const Forest& forest, const BoundaryMaps& maps, std::span<Block* const> blocks, int rank,
                 MPI_Comm comm, const std::array<int, 3>& stagger);
  // Collective. The groups must all have this correction's staggering.
  void run(const VariableRegistry& vars, std::span<const int> edge_groups);
  std::size_t transfers() const { return same_.all.size() + fine_.all.size(); }

 private:
  // Values of one source block for one destination block.
  struct Transfer {
    std::int64_t src_gid = -1, dst_gid = -1;
    std::vector<std::array<int, 3>> points;  // destination-local edge points
    std::array<int, 3> shift{};              // source point: p + shift (same level), 2 p + shift (finer)
  };
  struct Pass {
    bool fine = false;
    std::vector<Transfer> all;
    std::vector<const Transfer*> local;
    std::map<int, std::vector<const Transfer*>> sends, recvs;
    std::size_t send_values = 0, recv_values = 0;  // points, summed
  };
  void plan_same_level(const Forest& forest, const BoundaryMaps& maps, std::int64_t gid);
  void plan_finer(const Forest& forest, const BoundaryMaps& maps, std::int64_t gid);
  void check_sources(const Pass& pass, const std::array<int, 3>& n) const;
  void sort_out(Pass& pass, const Forest& forest);
  void source_values(const Pass& pass, const Transfer& t, const Field& f, double* out) const;
  void run_pass(Pass& pass, const VariableRegistry& vars, std::span<const int> groups);
  Block& local_block(std::int64_t gid) const { return *blocks_[static_cast<std::size_t>(gid - first_gid_)]; }
  bool is_mine(std::int64_t gid) const { return gid >= first_gid_ && gid < first_gid_ + count_; }

  MPI_Comm comm_;
  int dimension_;
  std::array<int, 3> stagger_;
  std::vector<Block*> blocks_;
  std::int64_t first_gid_ = 0, count_ = 0;
  Pass same_, fine_;
  std::vector<double> send_buffer_, recv_buffer_, scratch_;
};

}  // namespace remnant::grid
