#include "boundary_ghosts.hpp"

#include <cmath>

namespace remnant::xcfc {
namespace {

// Dirichlet values at the outer faces (manufactured solutions only: a callback per ghost).
void fill_dirichlet(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous, int d,
                    int side) {
  const GridShape& s = L.shape;
  const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
  const Level::GhostFace& gf = L.ghost_faces[d][side];
  std::size_t t = 0;
  for (int t2 = 0; t2 < s.n[e2]; ++t2)
    for (int t1 = 0; t1 < s.n[e1]; ++t1, ++t) {
      std::array<int, 3> g{};
      g[d] = side == 0 ? -1 : s.n[d], g[e1] = t1, g[e2] = t2;
      Point3 xf = s.point(g[0], g[1], g[2]);
      xf[d] = s.face(d, side == 0 ? 0 : s.n[d]);
      const double inner = a[static_cast<std::size_t>(gf.inner[t])];
      a[static_cast<std::size_t>(gf.ghost[t])] = (homogeneous ? 0.0 : 2.0 * eq.dirichlet(xf)) - inner;
    }
}

}  // namespace

void fill_ghosts(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous) {
  const GridShape& s = L.shape;
  double* v = a.data();
  for (int d = 0; d < 3; ++d) {
    if (!s.used(d)) continue;
    for (int side = 0; side < 2; ++side) {
      if (s.boundary[d][side] == Boundary::interface) continue;
      const Level::GhostFace& gf = L.ghost_faces[d][side];
      const std::ptrdiff_t *g = gf.ghost.data(), *in = gf.inner.data(), *mi = gf.mirror.data();
      const std::size_t count = gf.ghost.size();
      if (s.boundary[d][side] != Boundary::outer) {
        const double parity = eq.parity[d][side];
        for (std::size_t t = 0; t < count; ++t) v[g[t]] = parity * v[mi[t]];
      } else if (eq.dirichlet) {
        fill_dirichlet(L, eq, a, homogeneous, d, side);
      } else {
        const double u_inf = homogeneous ? 0.0 : eq.far_value;
        const std::vector<double>& r = eq.falloff == 2.0 ? L.robin2[d][side] : L.robin1[d][side];
        const bool power = eq.falloff != 1.0 && eq.falloff != 2.0;
        for (std::size_t t = 0; t < count; ++t) {
          const double ratio = power ? std::pow(r[t], eq.falloff) : r[t];
          v[g[t]] = u_inf + (v[in[t]] - u_inf) * ratio;
        }
      }
    }
  }
}

}  // namespace remnant::xcfc
