#pragma once
// Between the Grid's block forest and the solver's composite grid. The base level (level 0 of the
// forest, as one array) and, with refinement, one patch per block of each finer level that is a
// leaf or an ancestor of leaves (CompositeLayout). Every rank holds the whole composite field: a
// gather is one MPI_Allreduce(SUM) of arrays in which each rank has filled its own leaf cells
// (exact: every leaf cell is written by one rank, the rest are zeros), so results are bit-identical
// for any number of ranks; covered cells then take the volume-weighted mean of their children.
#include <map>
#include <string>
#include <vector>

#include "XCFC/multigrid/composite_multigrid.hpp"
#include "remnant/context.hpp"

namespace remnant::xcfc {

// Throws std::invalid_argument naming the allowed kinds when the face (d, side) of the grid's domain
// is one the elliptic solver cannot take.
void check_face(const Domain& domain, int d, int side);

// The composite layout of the Grid's forest (its domain from GridDriver::domain()); throws RunError
// for faces the solver lacks.
CompositeLayout layout_of_grid(const Context& ctx);

class GridBridge {
 public:
  GridBridge(Context& ctx, const CompositeMultigrid& mg);
  // Gathers the interior of component `comp` of `group`.
  CompositeField gather(int group, int comp) const;
  // Gathers a value computed per cell on the owning rank: per_block(Block&) returns the cell
  // function value(i, j, k) of that block (so that its Fields are looked up once per block).
  template <class PerBlock>
  CompositeField gather_cells(PerBlock&& per_block) const {
    CompositeField out = mg_.field();
    for (Block* b : ctx_.grid().local_blocks()) {
      const Place pl = place(*b);
      std::vector<double>& part = out.part[static_cast<std::size_t>(pl.part)];
      const auto value = per_block(*b);
      for_interior(*b, [&](int i, int j, int k) { part[pl.index(i, j, k)] = value(i, j, k); });
    }
    complete(out);
    return out;
  }
  // Writes the leaf values of a composite field into the interior of the local blocks.
  void scatter(const CompositeField& a, int group, int comp) const;

 private:
  // Where a block's interior lies in the composite field: a part and the offset and row lengths of
  // the block's cell (0, 0, 0) there.
  struct Place {
    int part;
    std::array<std::int64_t, 3> offset;
    std::int64_t n0, n1;
    std::size_t index(int i, int j, int k) const {
      return static_cast<std::size_t>((offset[0] + i) + n0 * ((offset[1] + j) + n1 * (offset[2] + k)));
    }
  };
  Place place(const Block& b) const;
  void complete(CompositeField& f) const;  // allreduce, then covered cells from their children
  Context& ctx_;
  const CompositeMultigrid& mg_;
  std::vector<std::map<std::array<std::int64_t, 3>, int>> part_of_block_;  // per level >= 1
};

}  // namespace remnant::xcfc
