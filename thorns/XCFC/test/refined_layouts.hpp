#pragma once
// Refined layouts for the composite tests: nested boxes of refinement, 2:1 balanced as the Grid's
// forests are.
#include <array>
#include <cmath>
#include <vector>

#include "XCFC/multigrid/composite_multigrid.hpp"

namespace remnant::xcfc::test {

using Box = std::array<std::array<double, 2>, 3>;

// Level l + 1 patches: the children of every level-l block that meets the box and whose
// neighbours (corners included) all belong to level l, so the layout is 2:1 balanced.
inline CompositeLayout nested_layout(const GridShape& base, std::array<int, 3> patch_cells, const std::vector<Box>& boxes) {
  CompositeLayout lay;
  lay.base = base;
  lay.patch_cells = patch_cells;
  for (int d = base.dimension; d < 3; ++d) lay.patch_cells[d] = 1;
  // Level-l blocks as a set of block indices; level 0: all.
  std::vector<std::array<int, 3>> blocks;
  std::array<int, 3> nblk{1, 1, 1};
  for (int d = 0; d < base.dimension; ++d) nblk[d] = base.n[d] / lay.patch_cells[d];
  for (int k = 0; k < nblk[2]; ++k)
    for (int j = 0; j < nblk[1]; ++j)
      for (int i = 0; i < nblk[0]; ++i) blocks.push_back({i, j, k});
  for (std::size_t l = 0; l < boxes.size(); ++l) {
    auto has = [&](std::array<int, 3> b) {
      for (int d = 0; d < 3; ++d)
        if (b[d] < 0 || b[d] >= nblk[d]) return true;  // outside the domain: no constraint
      for (const auto& x : blocks)
        if (x == b) return true;
      return false;
    };
    const double scale = std::pow(0.5, static_cast<double>(l));
    std::vector<std::array<int, 3>> next;
    for (const auto& b : blocks) {
      bool meets = true, balanced = true;
      for (int d = 0; d < base.dimension; ++d) {
        const double width = base.dx[d] * scale * lay.patch_cells[d];
        const double a = base.lo[d] + b[d] * width, c = a + width;
        meets &= c > boxes[l][d][0] && a < boxes[l][d][1];
      }
      for (int oz = -1; oz <= 1; ++oz)
        for (int oy = -1; oy <= 1; ++oy)
          for (int ox = -1; ox <= 1; ++ox) {
            const std::array<int, 3> o{ox, oy, oz};
            std::array<int, 3> nbk = b;
            bool skip = false;
            for (int d = 0; d < 3; ++d) {
              if (d >= base.dimension && o[d] != 0) skip = true;
              nbk[d] += o[d];
            }
            if (!skip) balanced &= has(nbk);
          }
      if (!meets || !balanced) continue;
      for (int c = 0; c < (base.dimension > 2 ? 2 : 1); ++c)
        for (int bb = 0; bb < (base.dimension > 1 ? 2 : 1); ++bb)
          for (int a = 0; a < 2; ++a) next.push_back({2 * b[0] + a, 2 * b[1] + bb, 2 * b[2] + c});
    }
    if (next.empty()) break;
    for (int d = 0; d < base.dimension; ++d) nblk[d] *= 2;
    lay.patches.emplace_back();
    for (const auto& b : next)
      lay.patches.back().push_back({b[0] * lay.patch_cells[0], b[1] * lay.patch_cells[1], b[2] * lay.patch_cells[2]});
    blocks = next;
  }
  return lay;
}


}  // namespace remnant::xcfc::test
