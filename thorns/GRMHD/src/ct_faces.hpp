#pragma once
// The Riemann data of a block's faces for the edge EMFs (CtComponent of mhd_groups.hpp: HLL speed
// bounds, transport velocities, induction fluxes), as views shaped like the block's flux groups
// (GRMHD::flux_x/y/z: one ghost layer), so that the sweeps write them at the flux offsets.
//
// They are per-block scratch, not grid groups (issue 21: 216 B per cell as groups): uct_hll and
// arithmetic read only the block's own faces, so the RHS computes a block's EMFs right after its
// sweep and reuses one storage for every block; uct_contact reads the corrected mass fluxes, so it
// keeps the two induction fluxes of every block (CtFaceStorage per block) until the Grid has
// corrected them.
#include <array>
#include <cstddef>
#include <vector>

#include "groups.hpp"
#include "mhd_groups.hpp"
#include "remnant/grid.hpp"

namespace remnant::grmhd {

// f[d][q]: component q of the faces normal to d (index space of the flux group g.flux[d]).
struct CtFaces {
  std::array<std::array<Field, kNumCt>, 3> f{};
};

// Storage of components [first, last) of the face data of one block at a time. bind() reuses the
// storage while the blocks' flux groups keep their shape; a new shape gets zeroed storage (as a
// fresh group: the points the sweeps never write, e.g. the induction fluxes uct_hll skips, stay 0).
class CtFaceStorage {
 public:
  // Points `views`' components [first, last) of the three directions at this storage, shaped as
  // block b's flux groups g.flux; the other components of `views` are left as they are.
  void bind(Block& b, const Groups& g, CtFaces& views, int first = 0, int last = kNumCt);
  // All components for block b.
  CtFaces bind(Block& b, const Groups& g) {
    CtFaces v;
    bind(b, g, v);
    return v;
  }
  // The bound components of direction d, component-major (points_per_component of g.flux[d] each).
  double* data(int d) { return data_.data() + start_[d]; }
  std::size_t size(int d) const { return static_cast<std::size_t>(last_ - first_) * points_[d]; }
  // Bytes held (the tests check that it is one block's, not the grid's).
  std::size_t bytes() const { return data_.capacity() * sizeof(double); }

 private:
  std::vector<double> data_;
  std::array<std::array<int, 3>, 3> extent_{};
  std::array<std::size_t, 3> points_{}, start_{};
  int first_ = 0, last_ = 0;
};

}  // namespace remnant::grmhd
