#pragma once
// correct_edges, the constrained-transport analogue of refluxing: every coarse copy of an edge
// that is also an edge of finer blocks (it lies on the boundary of a finer region, touching it
// through a face, an edge or a corner of the coarse block) takes the mean of the two fine edges
// along it (the one coincident fine value where the edge runs along an unused direction). EMFs
// are covariant components, so an edge's line integral is its value times its coordinate length
// and the two fine halves weigh the same. Afterwards the coarse fluxes through a coarse/fine
// interface change by exactly the sum of the fine changes, and coarse blocks that share an edge
// update their shared faces alike. One message per peer; the plan is built once per mesh and
// staggering. Across mirror maps (reflect, axis, origin) nothing is corrected.
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
  std::size_t items() const { return items_.size(); }

 private:
  struct Item {
    std::int64_t fine_gid = -1, coarse_gid = -1;
    Box coarse_points;                 // coarse-local edge points to replace
    std::array<int, 3> fine_shift{};   // fine-local index = 2 * coarse-local index + fine_shift
  };
  struct Peer {
    std::vector<const Item*> items;
    std::size_t values = 0;
  };
  void fine_means(const Item& it, const Field& f, double* out) const;
  static void coarse_update(const Item& it, const Field& f, const double* in);
  Block& local_block(std::int64_t gid) const { return *blocks_[static_cast<std::size_t>(gid - first_gid_)]; }

  MPI_Comm comm_;
  int dimension_;
  std::array<int, 3> stagger_;
  std::vector<Block*> blocks_;
  std::int64_t first_gid_ = 0;
  std::vector<Item> items_;
  std::vector<const Item*> local_;
  std::map<int, Peer> sends_, recvs_;
  std::vector<double> send_buffer_, recv_buffer_, scratch_;
};

}  // namespace remnant::grid
