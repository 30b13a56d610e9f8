#include "fluxes.hpp"

#include <algorithm>
#include <cmath>

#include "remnant/limiters.hpp"

namespace remnant::advection {

void face_fluxes(const Setup& s, Block& b, const Field& u, const Field& flux, int d) {
  const std::ptrdiff_t stride = d == 0 ? 1 : d == 1 ? u.sj : u.sk;
  const double* xc = b.centroids(d);
  const int nd = b.n[d];
  const int ext[3] = {b.n[0] + (d == 0), b.n[1] + (d == 1), b.n[2] + (d == 2)};
  for (int k = 0; k < ext[2]; ++k)
    for (int j = 0; j < ext[1]; ++j)
      for (int i = 0; i < ext[0]; ++i) {
        const int idx[3] = {i, j, k};
        const int f = idx[d];  // the face between cells f - 1 and f
        const double* p = &u(i, j, k);
        // Face point: the face coordinate in d, centroids in the others.
        Point3 x{b.centroid(0, i), b.centroid(1, j), b.centroid(2, k)};
        x[static_cast<std::size_t>(d)] = b.face_coordinate(d, f);
        const double v = velocity(s, x)[static_cast<std::size_t>(d)];
        double state;
        if (v >= 0) {
          const double sl = mc_slope(p[-2 * stride], p[-stride], p[0], xc[f - 2], xc[f - 1], xc[f]);
          state = p[-stride] + sl * (x[static_cast<std::size_t>(d)] - xc[f - 1]);
        } else {
          const double sl = mc_slope(p[-stride], p[0], p[stride], xc[f - 1], xc[f], xc[f + 1]);
          state = p[0] + sl * (x[static_cast<std::size_t>(d)] - xc[f]);
        }
        flux(i, j, k) = v * state;
        (void)nd;
      }
}

void flux_divergence(Block& b, const Field* flux[3], int dimension, const Field& rhs) {
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) {
        double net = 0;
        for (int d = 0; d < dimension; ++d) {
          const int up[3] = {i + (d == 0), j + (d == 1), k + (d == 2)};
          const Field& F = *flux[d];
          net += F(up[0], up[1], up[2]) * b.face_area(d, up[0], up[1], up[2]) - F(i, j, k) * b.face_area(d, i, j, k);
        }
        rhs(i, j, k) = -net / b.cell_volume(i, j, k);
      }
}

double inverse_dt(const Setup& s, const Block& b, int dimension) {
  double inv = 0;
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) {
        const Point3 v = velocity(s, {b.centroid(0, i), b.centroid(1, j), b.centroid(2, k)});
        double sum = 0;
        for (int d = 0; d < dimension; ++d) sum += std::abs(v[static_cast<std::size_t>(d)]) / b.dx[static_cast<std::size_t>(d)];
        inv = std::max(inv, sum);
      }
  return inv;
}

}  // namespace remnant::advection
