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

// Volume-weighted restriction of interior values of the patches [p0, p1) of T (all by default) into
// their parents' covered cells in C (interior arrays through the accessors fine(p, q) and coarse(p, q)).
template <class Fine, class Coarse>
void restrict_tier(const Tier& T, const Tier& C, Fine&& fine, Coarse&& coarse, std::size_t p0 = 0, std::size_t p1 = SIZE_MAX) {
  std::vector<double> sum, vol;
  for (std::size_t p = p0; p < std::min(p1, T.patches.size()); ++p) {
    const Level& P = T.patches[p];
    const Level& Q = C.patches[static_cast<std::size_t>(T.parent[p])];
    sum.assign(Q.cells(), 0.0);
    vol.assign(Q.cells(), 0.0);
    for (int k = 0; k < P.shape.n[2]; ++k)
      for (int j = 0; j < P.shape.n[1]; ++j)
        for (int i = 0; i < P.shape.n[0]; ++i) {
          const std::size_t q = P.cell(i, j, k), qc = coarse_cell(T, C, p, i, j, k);
          sum[qc] += P.volume[q] * fine(p, q);
          vol[qc] += P.volume[q];
        }
    for (std::size_t qc = 0; qc < Q.cells(); ++qc)
      if (vol[qc] > 0) coarse(static_cast<std::size_t>(T.parent[p]), qc) = sum[qc] / vol[qc];
  }
}

// The solution in the covered cells of tier t - 1 from the patches of tier t (ghosts filled): the
// children's mean minus (h^2 / 8) u_dd per direction, u_dd from the children's second differences.
// The composite discretisation reads covered values as point values (in the stencils of the
// neighbouring coarse leaf cells and in the fine ghosts' interpolation); a plain or volume-weighted
// mean would be off by O(H^2) there, an O(1) truncation error along the interface.
// Only the patches [p0, p1) of T (all by default).
void restrict_point_values(const Tier& T, Tier& C, std::size_t p0 = 0, std::size_t p1 = SIZE_MAX);

// The footprint of patch p of T in its parent patch of C: the parent and its interior cell range
// [lo, lo + n) per direction (the covered cells that p's cells restrict into).
struct Footprint {
  std::size_t parent;
  std::array<int, 3> lo, n;
};
Footprint footprint(const Tier& T, const Tier& C, std::size_t p);

}  // namespace remnant::xcfc
