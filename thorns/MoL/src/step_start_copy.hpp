#pragma once
// The evolved groups at the start of a Runge-Kutta step, kept for the substeps' u0. Only the
// interior points are kept (the update never reads u0 in the ghosts): with 16^3 blocks and 3 ghost
// layers this is 4096 instead of 10648 points per cell-centred component (issue 21, goal 7).
#include <cstddef>
#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "remnant/grid.hpp"

namespace remnant::mol {

// Interior points of a group along each direction: cells, and for staggered groups the faces or
// edges of the interior with both block faces (n + 1 along a used staggered direction).
std::array<int, 3> interior_points(const Block& b, Centering c);

class StepStartCopy {
 public:
  // Copies the interior of `groups` of every block in `blocks`; copies of blocks no longer listed
  // are dropped (a regrid moved or derefined them).
  void save(std::span<Block* const> blocks, const std::vector<int>& groups, const VariableRegistry& vars);
  // The saved row (j, k) of component c of group g of block gid: interior_points(..)[0] values.
  const double* row(std::int64_t gid, int g, int c, int j, int k) const;
  // Bytes held (capacity), for the memory accounting test and reports.
  std::size_t bytes() const;

 private:
  struct Copy {
    std::array<int, 3> points{};
    std::vector<double> values;  // component-major, then k, j, i
  };
  std::map<std::pair<std::int64_t, int>, Copy> copies_;
  std::vector<std::int64_t> blocks_;
};

}  // namespace remnant::mol
