#pragma once
// Reference-metric quantities at cell centroids and faces of a block (remnant/coordinates.hpp).
#include <array>
#include <cmath>
#include <vector>

#include "remnant/coordinates.hpp"
#include "remnant/grid.hpp"

namespace remnant {

inline Point3 cell_point(const Block& b, int i, int j, int k) { return {b.centroid(0, i), b.centroid(1, j), b.centroid(2, k)}; }

// d[i][j] = partial_i f_jj, from Gamma^j_ji = partial_i f_jj / (2 f_jj) (diagonal f).
inline std::array<std::array<double, 3>, 3> metric_diagonal_derivatives(const Point3& f, const Christoffels& g) {
  std::array<std::array<double, 3>, 3> d{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d[i][j] = 2.0 * f[j] * g[j][j][i];
  return d;
}

inline bool direction_used(const Block& b, int d) { return b.ng[d] > 0 || b.n[d] > 1; }

// Sine and cosine of the polar angle at a spherical block's cell centroids (index j, ghosts
// included) and theta faces: one sin/cos per row instead of one per cell (coords:: overloads that
// take them give the same bits). Empty for other coordinates.
struct PolarTrig {
  std::vector<double> sin_c, cos_c, sin_f;  // offset by the ghosts: use the accessors
  int ng = 0;
  explicit PolarTrig(const Block& b) {
    if (b.coordinates != CoordinateSystem::spherical) return;
    ng = b.ng[1];
    for (int j = -ng; j < b.n[1] + ng; ++j) {
      sin_c.push_back(std::sin(b.centroid(1, j)));
      cos_c.push_back(std::cos(b.centroid(1, j)));
    }
    for (int j = -ng; j <= b.n[1] + ng; ++j) sin_f.push_back(std::sin(b.face_coordinate(1, j)));
  }
  double sin_centre(int j) const { return sin_c.empty() ? 0.0 : sin_c[static_cast<std::size_t>(j + ng)]; }
  double cos_centre(int j) const { return cos_c.empty() ? 0.0 : cos_c[static_cast<std::size_t>(j + ng)]; }
  double sin_face(int j) const { return sin_f.empty() ? 0.0 : sin_f[static_cast<std::size_t>(j + ng)]; }
};

}  // namespace remnant
