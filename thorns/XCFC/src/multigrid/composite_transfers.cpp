#include "composite_transfers.hpp"

namespace remnant::xcfc {

std::size_t coarse_cell(const Tier& T, const Tier& C, std::size_t p, int i, int j, int k) {
  const Cell& F = T.corner[p];
  const Cell& Pc = C.corner[static_cast<std::size_t>(T.parent[p])];
  const std::array<int, 3> f{i, j, k};
  std::array<int, 3> g{0, 0, 0};
  for (int d = 0; d < 3; ++d)
    if (T.shape.used(d)) g[d] = static_cast<int>((F[d] + f[d]) / 2 - Pc[d]);
  return C.patches[static_cast<std::size_t>(T.parent[p])].cell(g[0], g[1], g[2]);
}

Footprint footprint(const Tier& T, const Tier& C, std::size_t p) {
  Footprint f{static_cast<std::size_t>(T.parent[p]), {0, 0, 0}, {1, 1, 1}};
  const Cell& F = T.corner[p];
  const Cell& Pc = C.corner[f.parent];
  for (int d = 0; d < 3; ++d)
    if (T.shape.used(d)) f.lo[d] = static_cast<int>(F[d] / 2 - Pc[d]), f.n[d] = T.nb[d] / 2;
  return f;
}

void restrict_point_values(const Tier& T, Tier& C, std::size_t p0, std::size_t p1) {
  std::array<int, 3> half{1, 1, 1};
  int dims = 0;
  for (int d = 0; d < 3; ++d)
    if (T.shape.used(d)) half[d] = T.nb[d] / 2, ++dims;
  const int children = 1 << dims;
  for (std::size_t p = p0; p < std::min(p1, T.patches.size()); ++p) {
    const Level& P = T.patches[p];
    Level& Q = C.patches[static_cast<std::size_t>(T.parent[p])];
    const Cell& F = T.corner[p];
    const Cell& Pc = C.corner[static_cast<std::size_t>(T.parent[p])];
    const double* u = P.u.data();
    for (int ck = 0; ck < half[2]; ++ck)
      for (int cj = 0; cj < half[1]; ++cj)
        for (int ci = 0; ci < half[0]; ++ci) {
          const std::array<int, 3> c{ci, cj, ck};
          std::array<int, 3> f0{0, 0, 0}, cc{0, 0, 0};
          for (int d = 0; d < 3; ++d)
            if (T.shape.used(d)) f0[d] = 2 * c[d], cc[d] = static_cast<int>(F[d] / 2 - Pc[d]) + c[d];
          const std::ptrdiff_t g0 = P.at(f0[0], f0[1], f0[2]);
          double mean = 0, curvature = 0;
          for (int b = 0; b < children; ++b) {
            std::ptrdiff_t g = g0;
            int bit = 0;
            for (int d = 0; d < 3; ++d)
              if (T.shape.used(d)) g += ((b >> bit++) & 1) * P.st[d];
            mean += u[g];
            bit = 0;
            for (int d = 0; d < 3; ++d) {
              if (!T.shape.used(d)) continue;
              const std::ptrdiff_t sd = P.st[d];
              if (((b >> bit++) & 1) == 0) curvature += 0.5 * (u[g + 2 * sd] - u[g + sd] - u[g] + u[g - sd]);
            }
          }
          Q.u[static_cast<std::size_t>(Q.at(cc[0], cc[1], cc[2]))] = mean / children - curvature / (8.0 * (children / 2));
        }
  }
}

}  // namespace remnant::xcfc
