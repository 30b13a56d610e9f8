#pragma once
// Between the Grid's block forest and the solver's structured grid. The solver works on the whole
// uniform level on every rank: a gather is one MPI_Allreduce(SUM) of arrays in which each rank has
// filled its own cells (exact: every cell is written by one rank, the rest are zeros), so results
// are bit-identical for any number of ranks. A grid with blocks on several levels is refused.
#include <vector>

#include "XCFC/structured_grid.hpp"
#include "remnant/context.hpp"

namespace remnant::xcfc {

// The structured grid of the Grid's (single) level; throws RunError for a refined grid.
GridShape shape_of_grid(const Context& ctx);

class GridBridge {
 public:
  GridBridge(Context& ctx, const GridShape& shape);
  // Global cell index of interior cell (i, j, k) of a block.
  std::size_t global_index(const Block& b, int i, int j, int k) const;
  // Gathers the interior of component `comp` of `group` (times nothing) into a global array.
  std::vector<double> gather(int group, int comp) const;
  // Gathers a value computed per cell on the owning rank.
  template <class F>
  std::vector<double> gather_cells(F&& value) const {
    std::vector<double> out(shape_.cells(), 0.0);
    for (Block* b : ctx_.grid().local_blocks())
      for_interior(*b, [&](int i, int j, int k) { out[global_index(*b, i, j, k)] = value(*b, i, j, k); });
    allreduce(out);
    return out;
  }
  // Writes a global array into the interior of the local blocks.
  void scatter(const std::vector<double>& a, int group, int comp) const;

 private:
  void allreduce(std::vector<double>& a) const;
  Context& ctx_;
  GridShape shape_;
};

}  // namespace remnant::xcfc
