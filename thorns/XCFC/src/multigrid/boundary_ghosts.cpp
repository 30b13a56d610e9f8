#include "boundary_ghosts.hpp"

#include <algorithm>
#include <cmath>

namespace remnant::xcfc {
namespace {

// Dirichlet values at the outer faces (manufactured solutions only: a callback per ghost).
void fill_dirichlet(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous, int d,
                    int side, const std::array<int, 3>& lo, const std::array<int, 3>& hi, std::ptrdiff_t b0) {
  const GridShape& s = L.shape;
  const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
  const Level::GhostFace& gf = L.ghost_faces[d][side];
  for (int t2 = lo[e2]; t2 < hi[e2]; ++t2)
    for (int t1 = lo[e1]; t1 < hi[e1]; ++t1) {
      const auto t = static_cast<std::size_t>(t1 + s.n[e1] * t2);
      std::array<int, 3> g{};
      g[d] = side == 0 ? -1 : s.n[d], g[e1] = t1, g[e2] = t2;
      Point3 xf = s.point(g[0], g[1], g[2]);
      xf[d] = s.face(d, side == 0 ? 0 : s.n[d]);
      const double inner = a[static_cast<std::size_t>(gf.inner[t] - b0)];
      a[static_cast<std::size_t>(gf.ghost[t] - b0)] = (homogeneous ? 0.0 : 2.0 * eq.dirichlet(xf)) - inner;
    }
}

}  // namespace

std::size_t fill_ghosts(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous,
                        const GhostBox& box, std::ptrdiff_t base) {
  std::size_t filled = 0;
  const std::ptrdiff_t b0 = base == kLevelBase ? L.gbase : base;  // the face lists hold global offsets
  const GridShape& s = L.shape;
  double* v = a.data();
  std::array<int, 3> lo{}, hi{};  // the box's interior cells
  for (int d = 0; d < 3; ++d) lo[d] = std::max(0, box.b[d]), hi[d] = std::min(s.n[d], box.e[d]);
  for (int d = 0; d < 3; ++d) {
    if (!s.used(d)) continue;
    const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      if (s.boundary[d][side] == Boundary::interface) continue;
      if (side == 0 ? box.b[d] > 0 : box.e[d] < s.n[d]) continue;  // the box does not reach this face
      const Level::GhostFace& gf = L.ghost_faces[d][side];
      const std::ptrdiff_t *g = gf.ghost.data(), *in = gf.inner.data(), *mi = gf.mirror.data();
      // Face entries t = t1 + n[e1] * t2 of the box: runs of consecutive t.
      filled += static_cast<std::size_t>(hi[e1] - lo[e1]) * static_cast<std::size_t>(hi[e2] - lo[e2]);
      auto for_runs = [&](auto&& run) {
        if (lo[e1] == 0 && hi[e1] == s.n[e1])  // whole rows of the face: one run
          return run(static_cast<std::size_t>(s.n[e1] * lo[e2]), static_cast<std::size_t>(s.n[e1] * hi[e2]));
        for (int t2 = lo[e2]; t2 < hi[e2]; ++t2) {
          const auto t0 = static_cast<std::size_t>(lo[e1] + s.n[e1] * t2);
          run(t0, t0 + static_cast<std::size_t>(hi[e1] - lo[e1]));
        }
      };
      if (s.boundary[d][side] != Boundary::outer) {
        const double parity = eq.parity[d][side];
        for_runs([&](std::size_t t0, std::size_t t1) {
          for (std::size_t t = t0; t < t1; ++t) v[g[t] - b0] = parity * v[mi[t] - b0];
        });
      } else if (eq.dirichlet) {
        fill_dirichlet(L, eq, a, homogeneous, d, side, lo, hi, b0);
      } else {
        const double u_inf = homogeneous ? 0.0 : eq.far_value;
        const std::vector<double>& r = eq.falloff == 2.0 ? L.robin2[d][side] : L.robin1[d][side];
        const bool power = eq.falloff != 1.0 && eq.falloff != 2.0;
        for_runs([&](std::size_t t0, std::size_t t1) {
          for (std::size_t t = t0; t < t1; ++t) {
            const double ratio = power ? std::pow(r[t], eq.falloff) : r[t];
            v[g[t] - b0] = u_inf + (v[in[t] - b0] - u_inf) * ratio;
          }
        });
      }
    }
  }
  return filled;
}

}  // namespace remnant::xcfc
