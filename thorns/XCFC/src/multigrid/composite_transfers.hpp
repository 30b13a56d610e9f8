#pragma once
// Transfers between a composite level (tier) and the next coarser one: the coarse cell of a fine
// cell, volume-weighted restriction into covered cells, and the point-value restriction of the
// solution.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "composite_tier.hpp"

namespace remnant::xcfc {

// Interior index, in the parent patch, of the coarse cell holding fine cell (i, j, k) of patch p.
std::size_t coarse_cell(const Tier& T, const Tier& C, std::size_t p, int i, int j, int k);

// The footprint of patch p of T in its parent patch of C: the parent and its interior cell range
// [lo, lo + n) per direction (the covered cells that p's cells restrict into).
struct Footprint {
  std::size_t parent;
  std::array<int, 3> lo, n;
};
Footprint footprint(const Tier& T, const Tier& C, std::size_t p);

// Volume-weighted restriction of interior values of the patches [p0, p1) of T (all by default) into
// their parents' covered cells in C (interior arrays through the accessors fine(p, q) and coarse(p, q)).
// Each coarse cell sums its children in the fine patch's storage order; the sums are kept over the
// footprint only (fine cell f lies in footprint cell f / 2: patch corners are even).
template <class Fine, class Coarse>
void restrict_tier(const Tier& T, const Tier& C, Fine&& fine, Coarse&& coarse, std::size_t p0 = 0, std::size_t p1 = SIZE_MAX) {
  std::vector<double> sum, vol;
  std::array<int, 3> half{1, 1, 1};
  for (int d = 0; d < 3; ++d)
    if (T.shape.used(d)) half[d] = 2;
  for (std::size_t p = p0; p < std::min(p1, T.patches.size()); ++p) {
    const Level& P = T.patches[p];
    const Footprint fp = footprint(T, C, p);
    const Level& Q = C.patches[fp.parent];
    const auto cells = static_cast<std::size_t>(fp.n[0]) * fp.n[1] * fp.n[2];
    sum.assign(cells, 0.0);
    vol.assign(cells, 0.0);
    for (int k = 0; k < P.shape.n[2]; ++k)
      for (int j = 0; j < P.shape.n[1]; ++j)
        for (int i = 0; i < P.shape.n[0]; ++i) {
          const std::size_t q = P.cell(i, j, k);
          const auto c = static_cast<std::size_t>(i / half[0] + fp.n[0] * (j / half[1] + fp.n[1] * (k / half[2])));
          sum[c] += P.volume[q] * fine(p, q);
          vol[c] += P.volume[q];
        }
    std::size_t c = 0;
    for (int k = 0; k < fp.n[2]; ++k)
      for (int j = 0; j < fp.n[1]; ++j)
        for (int i = 0; i < fp.n[0]; ++i, ++c)
          if (vol[c] > 0) coarse(fp.parent, Q.cell(fp.lo[0] + i, fp.lo[1] + j, fp.lo[2] + k)) = sum[c] / vol[c];
  }
}

// The solution in the covered cells of tier t - 1 from the patches of tier t (ghosts filled): the
// children's mean minus (h^2 / 8) u_dd per direction, u_dd from the children's second differences.
// The composite discretisation reads covered values as point values (in the stencils of the
// neighbouring coarse leaf cells and in the fine ghosts' interpolation); a plain or volume-weighted
// mean would be off by O(H^2) there, an O(1) truncation error along the interface.
// Only the patches [p0, p1) of T (all by default).
void restrict_point_values(const Tier& T, Tier& C, std::size_t p0 = 0, std::size_t p1 = SIZE_MAX);


}  // namespace remnant::xcfc
