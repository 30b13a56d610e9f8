#pragma once
// Refluxing: on a face shared by a coarse block and finer blocks, the coarse flux density is
// replaced by the area-weighted mean of the fine ones. The fine side sums flux * (tangential
// area weight) over the 2^(d-1) fine faces of each coarse face, the coarse side divides by its
// own tangential weight (the normal factor of the area is common to both). One message per
// (peer); the plan is built once per mesh.
#include <mpi.h>

#include <map>
#include <span>
#include <vector>

#include "boundary_map.hpp"
#include "box.hpp"
#include "forest.hpp"

namespace remnant::grid {

class FluxCorrection {
 public:
  FluxCorrection(const Forest& forest, const BoundaryMaps& maps, std::span<Block* const> blocks, int rank, MPI_Comm comm);
  // Collective. Each group must be face-centred (face_x, face_y or face_z).
  void run(const VariableRegistry& vars, std::span<const int> face_groups);
  std::size_t interfaces() const { return items_.size(); }

 private:
  struct Item {
    int direction = 0;
    std::int64_t fine_gid = -1, coarse_gid = -1;
    int fine_face = 0;          // local face index of the fine block in `direction` (0 or n)
    int coarse_face = 0;        // local face index of the coarse block (0 or n)
    Box coarse_tangential;      // coarse-local tangential cell range (the face index is coarse_face)
    std::array<int, 3> fine_offset{};  // fine-local cell index of coarse-local tangential cell 0, times 2 applied
    std::size_t values() const { return coarse_tangential.points(); }
  };
  struct Peer {
    std::vector<const Item*> items;
    std::size_t values = 0;
  };
  void fine_sums(const Item& it, Block& fine, const Field& flux, double* out) const;
  void coarse_update(const Item& it, Block& coarse, const Field& flux, const double* in) const;
  Block& local_block(std::int64_t gid) const { return *blocks_[static_cast<std::size_t>(gid - first_gid_)]; }

  MPI_Comm comm_;
  int dimension_;
  std::vector<Block*> blocks_;
  std::int64_t first_gid_ = 0;
  std::vector<Item> items_;
  std::vector<const Item*> local_;
  std::map<int, Peer> sends_, recvs_;
  std::vector<double> send_buffer_, recv_buffer_, scratch_;
};

}  // namespace remnant::grid
