#pragma once
// Reference-metric quantities at cell centroids and faces of a block (remnant/coordinates.hpp).
#include <array>

#include "remnant/coordinates.hpp"
#include "remnant/grid.hpp"

namespace remnant::grmhd {

inline Point3 cell_point(const Block& b, int i, int j, int k) { return {b.centroid(0, i), b.centroid(1, j), b.centroid(2, k)}; }

// d[i][j] = partial_i f_jj, from Gamma^j_ji = partial_i f_jj / (2 f_jj) (diagonal f).
inline std::array<std::array<double, 3>, 3> metric_diagonal_derivatives(const Point3& f, const Christoffels& g) {
  std::array<std::array<double, 3>, 3> d{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d[i][j] = 2.0 * f[j] * g[j][j][i];
  return d;
}

inline bool direction_used(const Block& b, int d) { return b.ng[d] > 0 || b.n[d] > 1; }

}  // namespace remnant::grmhd
