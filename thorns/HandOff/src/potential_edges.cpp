// The vector potential's edge integrals from the 3D data's fluxes (potential_edges.hpp).
#include "potential_edges.hpp"

#include <cmath>

#include "remnant/cell_geometry.hpp"

namespace remnant::handoff {
namespace {

// 2D cylindrical (march along R from the axis, fluxes through z faces) or spherical (along theta
// from the pole, through r faces): 2 pi A_phi = Psi at every node of the frame.
// closure: the largest |Psi at the grid's far end| / sum |flux| of a row with field at its far end
// that is taken for the data's interpolation error and removed (HandOff::flux_closure_tolerance).
EdgeTable axisymmetric_edges(const Frame& fr, bool cyl, const FluxQuadrature& q, double closure) {
  const int m = cyl ? 0 : 1, d = cyl ? 1 : 0;
  const auto um = static_cast<std::size_t>(m), ud = static_cast<std::size_t>(d);
  const LevelFaces& F = fr.F;
  EdgeTable t(fr);
  const double phi_lo = F(2, 0), phi_hi = fr.phi_hi;
  std::vector<double> psi(static_cast<std::size_t>(fr.cells[um] + 1)), weight(static_cast<std::size_t>(fr.cells[um] + 1));
  for (int fd = 0; fd <= fr.n[ud]; ++fd) {
    const double xd = F(d, fr.first[ud] + fd);
    // Psi and the cumulative |flux| at every node of the row, from the axis to the grid's far end.
    psi[0] = weight[0] = 0;
    double last = 0;  // the flux through the row's last face
    for (std::int64_t g = 0; g < fr.cells[um]; ++g) {
      Point3 lo{}, hi{};
      lo[um] = F(m, g), hi[um] = F(m, g + 1), lo[2] = phi_lo, hi[2] = phi_hi;
      const double f = q.flux(d, xd, lo, hi);
      const auto u = static_cast<std::size_t>(g);
      psi[u + 1] = psi[u] + f, weight[u + 1] = weight[u] + std::abs(f), last = f;
    }
    // A field that closes inside the grid (none at the row's far end, or a net flux below
    // closure of the row's |flux|) has Psi = 0 there; what is left is the interpolation error of
    // the data: removed in proportion to |flux| (so nothing is added where the data have no field).
    const double total = weight.back(), leak = psi.back();
    const bool close = total > 0 && (last == 0.0 || std::abs(leak) <= closure * total);
    for (int fm = 0; fm <= fr.n[um]; ++fm) {
      const auto u = static_cast<std::size_t>(fr.first[um] + fm);
      t(2, cyl ? fm : fd, cyl ? fd : fm, 0) = close ? psi[u] - leak * (weight[u] / total) : psi[u];
    }
  }
  return t;
}


// 3D: the axial gauge A_g = 0 (potential_edges.hpp). sign: the orientation that turns the
// fluxes into circulations for the order (p, q, g) (vector_potential.hpp: (R, z, phi) is
// left-handed).
struct GaugeRoles {
  int p = 0, q = 1, g = 2;
  double sign = 1.0;
};
GaugeRoles gauge_roles(CoordinateSystem cs) {
  if (cs == CoordinateSystem::cylindrical) return {0, 2, 1, 1.0};  // odd order, left-handed axes
  if (cs == CoordinateSystem::spherical) return {1, 2, 0, 1.0};
  return {0, 1, 2, 1.0};
}

// The flux through the face of a level normal to d at face index fd, spanning the cells c1
// (direction e1) and c2 (e2); a periodic direction's last face is its first.
struct LevelFlux {
  const Frame& fr;
  const FluxQuadrature& of;
  const std::array<bool, 3>& periodic;
  double operator()(int d, std::int64_t fd, int e1, std::int64_t c1, int e2, std::int64_t c2) const {
    const auto ud = static_cast<std::size_t>(d);
    const LevelFaces& F = fr.F;
    if (periodic[ud] && fd == fr.cells[ud]) fd = 0;
    Point3 lo{}, hi{};
    lo[static_cast<std::size_t>(e1)] = F(e1, c1), hi[static_cast<std::size_t>(e1)] = F(e1, c1 + 1);
    lo[static_cast<std::size_t>(e2)] = F(e2, c2), hi[static_cast<std::size_t>(e2)] = F(e2, c2 + 1);
    return of.flux(d, F(d, fd), lo, hi);
  }
};

EdgeTable gauge_edges(const Frame& fr, const FluxQuadrature& flux_of, const std::array<bool, 3>& periodic, CoordinateSystem cs) {
  const GaugeRoles R = gauge_roles(cs);
  const int p = R.p, q = R.q, g = R.g;
  const auto up = static_cast<std::size_t>(p), uq = static_cast<std::size_t>(q), ug = static_cast<std::size_t>(g);
  const std::int64_t gp = fr.first[up], gq = fr.first[uq], gg = fr.first[ug];
  const std::int64_t top = gg + fr.n[ug];
  EdgeTable t(fr);
  auto at = [&](int a, std::int64_t ip, std::int64_t iq, std::int64_t ig) -> double& {
    int idx[3];
    idx[up] = static_cast<int>(ip), idx[uq] = static_cast<int>(iq), idx[ug] = static_cast<int>(ig);
    return t(a, idx[0], idx[1], idx[2]);
  };
  const LevelFlux flux{fr, flux_of, periodic};
  // A_q along q edges at p faces (ip), q cells (iq): base from the g faces of the lowest g face.
  for (int iq = 0; iq < fr.n[uq]; ++iq) {
    double base = 0;
    for (std::int64_t G = 0; G <= gp + fr.n[up]; ++G) {
      if (G >= gp) {
        double a = base;  // along g: A_q(k + 1) = A_q(k) - flux through the p face of cell k
        for (std::int64_t h = 0; h <= top; ++h) {
          if (h >= gg) at(q, G - gp, iq, h - gg) = a;
          if (h == top) break;
          a -= R.sign * flux(p, G, q, gq + iq, g, h);
        }
      }
      if (G == gp + fr.n[up]) break;
      base += R.sign * flux(g, 0, p, G, q, gq + iq);
    }
  }
  // A_p along p edges at p cells (ip), q faces (iq): zero on the lowest g face, + flux through q faces.
  for (int iq = 0; iq <= fr.n[uq]; ++iq)
    for (int ip = 0; ip < fr.n[up]; ++ip) {
      double a = 0;
      for (std::int64_t h = 0; h <= top; ++h) {
        if (h >= gg) at(p, ip, iq, h - gg) = a;
        if (h == top) break;
        a += R.sign * flux(q, gq + iq, p, gp + ip, g, h);
      }
    }
  return t;
}

// gauge_edges's values one period further along the periodic directions (shift: -1, 0, +1 per
// direction) minus its values: the sums start at the grid's lower faces, so with a net flux
// through a period the potential is periodic only up to these sums (A_q gains the flux through
// the lowest g plane's row along p; A_q and A_p the fluxes through a whole column along g).
EdgeTable gauge_period_jumps(const Frame& fr, const FluxQuadrature& flux_of, const std::array<bool, 3>& periodic,
                             CoordinateSystem cs, const std::array<int, 3>& shift) {
  const GaugeRoles R = gauge_roles(cs);
  const int p = R.p, q = R.q, g = R.g;
  const auto up = static_cast<std::size_t>(p), uq = static_cast<std::size_t>(q), ug = static_cast<std::size_t>(g);
  const std::int64_t gp = fr.first[up], gq = fr.first[uq];
  EdgeTable t(fr);
  const LevelFlux flux{fr, flux_of, periodic};
  auto at = [&](int a, std::int64_t ip, std::int64_t iq, std::int64_t ig) -> double& {
    int idx[3];
    idx[up] = static_cast<int>(ip), idx[uq] = static_cast<int>(iq), idx[ug] = static_cast<int>(ig);
    return t(a, idx[0], idx[1], idx[2]);
  };
  const int sp = shift[up], sg = shift[ug];
  for (int iq = 0; iq < fr.n[uq]; ++iq) {  // A_q: p faces (ip), q cells
    double row = 0;                          // along p through the lowest g plane
    if (sp != 0)
      for (std::int64_t G = 0; G < fr.cells[up]; ++G) row += R.sign * flux(g, 0, p, G, q, gq + iq);
    for (int ip = 0; ip <= fr.n[up]; ++ip) {
      double column = 0;  // along g through the p face
      if (sg != 0)
        for (std::int64_t h = 0; h < fr.cells[ug]; ++h) column -= R.sign * flux(p, gp + ip, q, gq + iq, g, h);
      for (int ig = 0; ig <= fr.n[ug]; ++ig) at(q, ip, iq, ig) = sp * row + sg * column;
    }
  }
  if (sg != 0)
    for (int iq = 0; iq <= fr.n[uq]; ++iq)  // A_p: p cells, q faces
      for (int ip = 0; ip < fr.n[up]; ++ip) {
        double column = 0;
        for (std::int64_t h = 0; h < fr.cells[ug]; ++h) column += R.sign * flux(q, gq + iq, p, gp + ip, g, h);
        for (int ig = 0; ig <= fr.n[ug]; ++ig) at(p, ip, iq, ig) = sg * column;
      }
  return t;
}

}  // namespace

Frame EdgeBuilder::frame(const Block& b, const BlockKey& key) const {
  Frame f;
  const double scale = std::ldexp(1.0, b.level - key.level);  // exact: spacings halve per level
  for (std::size_t d = 0; d < 3; ++d) {
    f.used[d] = direction_used(b, static_cast<int>(d));
    f.n[d] = b.n[d];
    f.first[d] = f.used[d] ? key.index[d] * b.n[d] : 0;
    f.F.domain_lo[d] = xmin[d];
    f.F.dx[d] = f.used[d] ? b.dx[d] * scale : b.dx[d];
    f.cells[d] = f.used[d] ? static_cast<std::int64_t>(std::llround((xmax[d] - xmin[d]) / f.F.dx[d])) : 1;
  }
  if (phi_average) {
    f.F.domain_lo[2] = b.face_coordinate(2, 0);
    f.phi_hi = b.face_coordinate(2, 1);
  }
  return f;
}

EdgeTable EdgeBuilder::edges(const Frame& f) const {
  return phi_average ? axisymmetric_edges(f, cs == CoordinateSystem::cylindrical, q, closure) : gauge_edges(f, q, periodic, cs);
}

EdgeTable EdgeBuilder::period_jumps(const Frame& f, const std::array<int, 3>& shift) const {
  // 2D: Psi of a row marches along R (theta) only, so it is periodic in z (r) as it is.
  return phi_average ? EdgeTable(f) : gauge_period_jumps(f, q, periodic, cs, shift);
}

void match_finer_leaves(const Block& b, const Frame& fb, const EdgeBuilder& builder, std::span<const BlockKey> leaves,
                        EdgeTable& t) {
  for (const BlockKey& key : leaves) {
    if (key.level != b.level + 1) continue;
    const Frame ff = builder.frame(b, key);
    // The leaf's position, shifted by a period where it touches b across a periodic face.
    std::array<std::int64_t, 3> first = ff.first;
    std::array<int, 3> periods{};  // the shift in periods, per direction
    bool touches = true;  // closed boxes intersect (in the coarse level's indices, times 2)
    for (std::size_t d = 0; d < 3 && touches; ++d) {
      if (!fb.used[d]) continue;
      auto meets = [&](std::int64_t f) { return 2 * fb.first[d] <= f + ff.n[d] && f <= 2 * (fb.first[d] + fb.n[d]); };
      touches = meets(first[d]);
      for (const std::int64_t shift : {-ff.cells[d], ff.cells[d]})
        if (!touches && builder.periodic[d] && meets(first[d] + shift)) {
          touches = true, first[d] += shift;
          periods[d] = shift > 0 ? 1 : -1;
        }
    }
    if (!touches) continue;
    EdgeTable fine = builder.edges(ff);
    // Seen across a periodic face the leaf's edges are those one period away: the potential's
    // sums from the grid's lower faces gain the net flux through a period there.
    if (periods != std::array<int, 3>{}) {
      const EdgeTable jump = builder.period_jumps(ff, periods);
      for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t m = 0; m < fine.value[a].size(); ++m) fine.value[a][m] += jump.value[a][m];
    }
    for (int a = 0; a < 3; ++a) {
      const auto& e = t.extent[static_cast<std::size_t>(a)];
      for (int k = 0; k < e[2]; ++k)
        for (int j = 0; j < e[1]; ++j)
          for (int i = 0; i < e[0]; ++i) {
            const std::array<int, 3> c{i, j, k};
            std::array<std::int64_t, 3> p{};  // the first fine edge, in the leaf's local indices
            for (std::size_t d = 0; d < 3; ++d) p[d] = fb.used[d] ? 2 * (fb.first[d] + c[d]) - first[d] : 0;
            std::array<std::int64_t, 3> p2 = p;  // the second half along a used edge direction
            const bool halves = fb.used[static_cast<std::size_t>(a)];
            if (halves) p2[static_cast<std::size_t>(a)] += 1;
            if (!fine.contains(a, p) || !fine.contains(a, p2)) continue;
            double v = fine(a, static_cast<int>(p[0]), static_cast<int>(p[1]), static_cast<int>(p[2]));
            if (halves) v += fine(a, static_cast<int>(p2[0]), static_cast<int>(p2[1]), static_cast<int>(p2[2]));
            t(a, i, j, k) = v;
          }
    }
  }
}


}  // namespace remnant::handoff
