// Geometry of the finite-volume Laplacian on one level: exact integrals of sqrt(f) f^dd over faces.
#include "level.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace remnant::xcfc {
namespace {

// The cell integral of g_e: unused directions have weight 1 (the factor cancels between volumes and
// face integrals).
double weight(const GridShape& s, int e, int i) {
  if (!s.used(e)) return 1.0;
  return coords::volume_factor_integral(s.coordinates, e, s.face(e, i), s.face(e, i + 1));
}

// The integral over cell i in direction e of g_e m_de, where f^dd = prod_e m_de(x^e) (separable).
double transverse_integral(const GridShape& s, int d, int e, int i) {
  if (!s.used(e)) return 1.0;
  const double a = s.face(e, i), b = s.face(e, i + 1);
  const CoordinateSystem cs = s.coordinates;
  if (cs == CoordinateSystem::spherical && e == 0 && d >= 1) return b - a;  // int r^2 / r^2 dr
  // Phi faces: int R / R^2 dR and int sin / sin^2 dtheta diverge at the axis, and only fields that
  // vary in phi cross them, which vanish there like varpi^m (m >= 1). The midpoint form
  // (b - a) / x_centre makes the flux exact for m = 1 and 2 with the cell value at the centre
  // (the log integrals are exact only for m = 0, and the centroid form is off by O(1) at the axis).
  const bool cyl_phi = cs == CoordinateSystem::cylindrical && d == 2 && e == 0;
  const bool sph_phi = cs == CoordinateSystem::spherical && d == 2 && e == 1;
  if (cyl_phi) return (b - a) / s.centre(e, i);
  if (sph_phi) return (b - a) / std::sin(s.centre(e, i));
  return weight(s, e, i);
}

// The average of 1/x over [a, b] with weight x^p: int x^(p-1) / int x^p.
double mean_inverse(double a, double b, int p) {
  if (p == 1) return (b - a) / (0.5 * (b * b - a * a));
  return (0.5 * (b * b - a * a)) / ((b * b * b - a * a * a) / 3.0);
}

}  // namespace

Level::Level(const GridShape& s) : shape(s) {
  for (int d = 0; d < 3; ++d) g[d] = s.used(d) ? 1 : 0;
  st[0] = 1;
  st[1] = s.n[0] + 2 * g[0];
  st[2] = st[1] * (s.n[1] + 2 * g[1]);
  ghosted_size = static_cast<std::size_t>(st[2]) * (s.n[2] + 2 * g[2]);
  stored_ghosted = ghosted_size;
  stored_cells = cells();
  const std::size_t nc = cells();
  volume.assign(nc, 0.0);
  diagonal.assign(nc, 0.0);
  for (int d = 0; d < 3; ++d) a_lo[d].assign(s.used(d) ? nc : 0, 0.0), a_hi[d].assign(s.used(d) ? nc : 0, 0.0);
  const CoordinateSystem cs = s.coordinates;
  // Only the geometries below have angular-mode terms: elsewhere (3D, Cartesian) the arrays stay
  // empty, read as zeros (3 doubles per cell of every level before; issue 21, goal 7).
  const bool m1 = (cs == CoordinateSystem::cylindrical && s.dimension <= 2) ||
                  (cs == CoordinateSystem::spherical && s.dimension == 2);
  const bool l1 = cs == CoordinateSystem::spherical && s.dimension == 1;
  if (m1) mode_k[static_cast<int>(AngularMode::axisymmetric_m1)].assign(nc, 0.0);
  if (l1) mode_k[static_cast<int>(AngularMode::spherical_l1)].assign(nc, 0.0);
  for (int k = 0; k < s.n[2]; ++k)
    for (int j = 0; j < s.n[1]; ++j)
      for (int i = 0; i < s.n[0]; ++i) {
        const std::size_t q = cell(i, j, k);
        const std::array<int, 3> ijk{i, j, k};
        const double vol = weight(s, 0, i) * weight(s, 1, j) * weight(s, 2, k);
        volume[q] = vol;
        double diag = 0;
        for (int d = 0; d < 3; ++d) {
          if (!s.used(d)) continue;
          double t = 1.0;
          for (int e = 0; e < 3; ++e)
            if (e != d) t *= transverse_integral(s, d, e, ijk[e]);
          const double c = t / (s.dx[d] * vol);
          a_lo[d][q] = c * coords::volume_factor(cs, d, s.face(d, ijk[d]));
          a_hi[d][q] = c * coords::volume_factor(cs, d, s.face(d, ijk[d] + 1));
          diag += a_lo[d][q] + a_hi[d][q];
        }
        diagonal[q] = diag;
        // Point terms of the angular modes, exact for a field linear in varpi (or r) near the axis:
        // k = <1/varpi> / varpi_centre with <.> the sqrt(f)-weighted cell average.
        const double a0 = s.face(0, i), b0 = s.face(0, i + 1);
        const Point3 x = s.point(i, j, k);
        if (cs == CoordinateSystem::cylindrical && s.dimension <= 2)
          mode_k[static_cast<int>(AngularMode::axisymmetric_m1)][q] = mean_inverse(a0, b0, 1) / x[0];
        if (cs == CoordinateSystem::spherical && s.dimension == 2) {
          const double a1 = s.face(1, j), b1 = s.face(1, j + 1);
          const double mean_inv_sin = (b1 - a1) / weight(s, 1, j);
          mode_k[static_cast<int>(AngularMode::axisymmetric_m1)][q] =
              mean_inverse(a0, b0, 2) * mean_inv_sin / (x[0] * std::sin(x[1]));
        }
        if (cs == CoordinateSystem::spherical && s.dimension == 1)
          mode_k[static_cast<int>(AngularMode::spherical_l1)][q] = 2.0 * mean_inverse(a0, b0, 2) / x[0];
      }
  for (double d : diagonal) max_diagonal = std::max(max_diagonal, d);
  const int longest = std::max({s.n[0], s.n[1], s.n[2]});
  // Line relaxation interleaves up to 4 lines (line_relaxation.cpp).
  for (auto* w : {&line_di, &line_rhs}) w->assign(4 * static_cast<std::size_t>(longest), 0.0);
  if (s.dimension <= 2)
    for (int d = 0; d < s.dimension; ++d) {
      const std::size_t lines = nc / static_cast<std::size_t>(s.n[d]);
      for (auto& c : end_c1[d]) c.assign(lines, 0.0);
      line_w[d].assign(nc, 0.0);
      line_inv[d].assign(nc, 0.0);
    }
  // Face ghosts: index lists, and for outer faces the Robin factors from the ghost's and the
  // inner cell's distances to the origin.
  for (int d = 0; d < 3; ++d) {
    if (!s.used(d)) continue;
    const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      GhostFace& gf = ghost_faces[d][side];
      const bool outer = s.boundary[d][side] == Boundary::outer;
      auto &f1 = robin1[d][side], &f2 = robin2[d][side];
      if (outer) f1.assign(static_cast<std::size_t>(s.n[e1]) * s.n[e2], 0.0), f2.assign(f1.size(), 0.0);
      std::size_t t = 0;
      for (int t2 = 0; t2 < s.n[e2]; ++t2)
        for (int t1 = 0; t1 < s.n[e1]; ++t1, ++t) {
          std::array<int, 3> gi{}, m{};
          gi[d] = side == 0 ? -1 : s.n[d], gi[e1] = t1, gi[e2] = t2;
          m = gi;
          m[d] = side == 0 ? 0 : s.n[d] - 1;
          gf.ghost.push_back(at(gi[0], gi[1], gi[2]));
          gf.inner.push_back(at(m[0], m[1], m[2]));
          const auto im = s.image({gi[0], gi[1], gi[2]}, d, side);
          gf.mirror.push_back(at(static_cast<int>(im[0]), static_cast<int>(im[1]), static_cast<int>(im[2])));
          if (!outer) continue;
          const Point3 Xi = coords::to_cartesian(cs, s.point(m[0], m[1], m[2]));
          const Point3 Xg = coords::to_cartesian(cs, s.point(gi[0], gi[1], gi[2]));
          const double ratio = std::hypot(Xi[0], Xi[1], Xi[2]) / std::hypot(Xg[0], Xg[1], Xg[2]);
          f1[t] = ratio;
          f2[t] = ratio * ratio;
        }
    }
  }
}

void Level::set_window(int lo, int hi) {
  const int s = shape.dimension - 1;
  const std::size_t nc = cells(), plane = nc / static_cast<std::size_t>(shape.n[s]);
  gbase = static_cast<std::ptrdiff_t>(lo - 1 + g[s]) * st[s];
  stored_ghosted = static_cast<std::size_t>(hi - lo + 2) * static_cast<std::size_t>(st[s]);
  cbase = static_cast<std::size_t>(lo) * plane;
  stored_cells = static_cast<std::size_t>(hi - lo) * plane;
  // A fresh vector of the window alone: its capacity is the window's.
  auto slice = [&](std::vector<double>& v) {
    if (v.size() != nc) return;
    const auto b = v.begin() + static_cast<std::ptrdiff_t>(cbase);
    v = std::vector<double>(b, b + static_cast<std::ptrdiff_t>(stored_cells));
  };
  for (auto* v : {&volume, &diagonal, &restrict_volume, &k, &s0, &s1, &s7, &f, &r, &k_eq}) slice(*v);
  for (int d = 0; d < 3; ++d)
    for (auto* v : {&a_lo[d], &a_hi[d], &mode_k[d], &line_w[d], &line_inv[d]}) slice(*v);
  u.clear(), ubar.clear();
}

std::size_t Level::stored_bytes() const {
  std::size_t n = 0;
  auto add = [&](const auto& v) { n += v.capacity() * sizeof(v[0]); };
  for (const auto* v : {&volume, &diagonal, &restrict_volume, &line_di, &line_rhs, &line_scratch, &line_z, &line_cyclic,
                        &shell_scratch, &dft_cos, &dft_sin, &k, &s0, &s1, &s7, &f, &r, &k_eq, &u, &ubar})
    add(*v);
  for (int d = 0; d < 3; ++d) {
    for (const auto* v : {&a_lo[d], &a_hi[d], &mode_k[d], &line_w[d], &line_inv[d]}) add(*v);
    for (int side = 0; side < 2; ++side) {
      for (const auto* v : {&robin1[d][side], &robin2[d][side], &end_c1[d][side]}) add(*v);
      const GhostFace& g = ghost_faces[d][side];
      for (const auto* v : {&g.ghost, &g.inner, &g.mirror}) add(*v);
    }
  }
  return n;
}

}  // namespace remnant::xcfc
