#include "XCFC/vector_poisson.hpp"

#include <algorithm>
#include <cmath>

namespace remnant::xcfc {

double VectorSolveStats::residual() const {
  double r = chi.scale > 0 ? chi.residual / chi.scale : 0;
  for (const auto& c : component) r = std::max(r, c.scale > 0 ? c.residual / c.scale : 0.0);
  return r;
}
bool VectorSolveStats::converged() const {
  return chi.converged && component[0].converged && component[1].converged && component[2].converged;
}

bool cartesian_component_active(const GridShape& s, int a) {
  return !(s.coordinates == CoordinateSystem::spherical && s.dimension == 1 && a != 0);
}

ScalarEquation cartesian_component_equation(const GridShape& s, int a) {
  ScalarEquation eq;
  const bool axisymmetric = s.coordinates != CoordinateSystem::cartesian && s.dimension <= 2;
  if (s.coordinates == CoordinateSystem::spherical && s.dimension == 1) {
    eq.mode = AngularMode::spherical_l1;
    eq.falloff = 2.0;  // exterior solution of Lap V - 2V/r^2 = 0: r^-2
  } else if (axisymmetric && a < 2) {
    eq.mode = AngularMode::axisymmetric_m1;
  }
  for (int d = 0; d < 3; ++d)
    for (int side = 0; side < 2; ++side) {
      double p = 1;
      switch (s.boundary[d][side]) {
        case Boundary::outer:
        case Boundary::interface: break;
        case Boundary::reflect:
          // Cartesian planes flip the normal component; the spherical equator and the cylindrical
          // z = 0 plane flip z.
          p = (s.coordinates == CoordinateSystem::cartesian ? a == d : a == 2) ? -1 : 1;
          break;
        case Boundary::axis:  // the mirror point lies at phi + pi: x and y flip
          p = a < 2 ? -1 : 1;
          break;
        case Boundary::origin:  // point reflection (with the equatorial mirror where theta is kept)
          p = s.dimension == 1 ? -1 : (a < 2 || !s.origin_flips_theta()) ? -1 : 1;
          break;
      }
      eq.parity[d][side] = p;
    }
  return eq;
}

ScalarEquation chi_equation() { return ScalarEquation{}; }

namespace {
template <class F>
void for_all_cells(const GridShape& s, int ghost, F&& f) {
  std::array<int, 3> g{};
  for (int d = 0; d < 3; ++d) g[d] = s.used(d) ? ghost : 0;
  for (int k = -g[2]; k < s.n[2] + g[2]; ++k)
    for (int j = -g[1]; j < s.n[1] + g[1]; ++j)
      for (int i = -g[0]; i < s.n[0] + g[0]; ++i) f(i, j, k);
}

// The transformations with the precomputed frames (interior cells; v^i = J[A][i] V^A / f_ii).
VectorField to_cartesian(const Multigrid& mg, const VectorField& up) {
  const GridShape& s = mg.shape();
  const CellFrames& fr = mg.frames();
  bool active[3];
  for (int a = 0; a < 3; ++a) active[a] = cartesian_component_active(s, a);
  VectorField out;
  for (auto& c : out) c.assign(s.cells(), 0.0);
  std::size_t q = 0;
  for_all_cells(s, 0, [&](int i, int j, int k) {
    const Matrix3& J = fr.J[static_cast<std::size_t>(mg.ghosted_index(i, j, k))];
    for (int a = 0; a < 3; ++a)
      if (active[a]) out[a][q] = J[a][0] * up[0][q] + J[a][1] * up[1][q] + J[a][2] * up[2][q];
    ++q;
  });
  return out;
}
Point3 from_cartesian(const CellFrames& fr, std::size_t p, double V0, double V1, double V2) {
  const Matrix3& J = fr.J[p];
  const Point3& f = fr.f[p];
  Point3 v;
  for (int c = 0; c < 3; ++c) v[c] = (J[0][c] * V0 + J[1][c] * V1 + J[2][c] * V2) / f[c];
  return v;
}
VectorField to_coordinate(const Multigrid& mg, const VectorField& cart) {
  const GridShape& s = mg.shape();
  const CellFrames& fr = mg.frames();
  VectorField out;
  for (auto& c : out) c.assign(s.cells(), 0.0);
  std::size_t q = 0;
  for_all_cells(s, 0, [&](int i, int j, int k) {
    const Point3 v = from_cartesian(fr, static_cast<std::size_t>(mg.ghosted_index(i, j, k)), cart[0][q], cart[1][q], cart[2][q]);
    for (int c = 0; c < 3; ++c) out[c][q] = v[c];
    ++q;
  });
  return out;
}
}  // namespace

VectorField to_cartesian_components(const GridShape& s, const VectorField& up) {
  VectorField out;
  for (auto& c : out) c.assign(s.cells(), 0.0);
  std::size_t q = 0;
  for_all_cells(s, 0, [&](int i, int j, int k) {
    const Point3 V = coords::vector_to_cartesian(s.coordinates, s.point(i, j, k), {up[0][q], up[1][q], up[2][q]});
    for (int a = 0; a < 3; ++a) out[a][q] = cartesian_component_active(s, a) ? V[a] : 0.0;
    ++q;
  });
  return out;
}

VectorField to_coordinate_components(const GridShape& s, const VectorField& cart) {
  VectorField out;
  for (auto& c : out) c.assign(s.cells(), 0.0);
  std::size_t q = 0;
  for_all_cells(s, 0, [&](int i, int j, int k) {
    const Point3 v = coords::vector_from_cartesian(s.coordinates, s.point(i, j, k), {cart[0][q], cart[1][q], cart[2][q]});
    for (int c = 0; c < 3; ++c) out[c][q] = v[c];
    ++q;
  });
  return out;
}

VectorField ghosted_coordinate_components(const Multigrid& mg, const VectorField& up) {
  const GridShape& s = mg.shape();
  const VectorField cart = to_cartesian(mg, up);
  VectorField gc;
  for (int a = 0; a < 3; ++a) gc[a] = mg.with_ghosts(cartesian_component_equation(s, a), cart[a]);
  VectorField out;
  for (auto& c : out) c.assign(gc[0].size(), 0.0);
  const CellFrames& fr = mg.frames();
  for_all_cells(s, 1, [&](int i, int j, int k) {
    const std::size_t p = static_cast<std::size_t>(mg.ghosted_index(i, j, k));
    const Point3 v = from_cartesian(fr, p, gc[0][p], gc[1][p], gc[2][p]);
    for (int c = 0; c < 3; ++c) out[c][p] = v[c];
  });
  return out;
}

std::vector<double> divergence(const Multigrid& mg, const VectorField& up) {
  const GridShape& s = mg.shape();
  const VectorField g = ghosted_coordinate_components(mg, up);
  const auto st = mg.ghosted_strides();
  // The face factors over the cell integral per direction and index: separable, so 1D tables.
  std::array<std::vector<double>, 3> lo_w, hi_w;
  for (int d = 0; d < s.dimension; ++d) {
    lo_w[d].resize(static_cast<std::size_t>(s.n[d]));
    hi_w[d].resize(static_cast<std::size_t>(s.n[d]));
    for (int i = 0; i < s.n[d]; ++i) {
      const double a = s.face(d, i), b = s.face(d, i + 1);
      const double w = coords::volume_factor_integral(s.coordinates, d, a, b);
      lo_w[d][static_cast<std::size_t>(i)] = coords::volume_factor(s.coordinates, d, a) / w;
      hi_w[d][static_cast<std::size_t>(i)] = coords::volume_factor(s.coordinates, d, b) / w;
    }
  }
  std::vector<double> div(s.cells(), 0.0);
  std::size_t q = 0;
  for_all_cells(s, 0, [&](int i, int j, int k) {
    const std::array<int, 3> ijk{i, j, k};
    const std::size_t p = static_cast<std::size_t>(mg.ghosted_index(i, j, k));
    double sum = 0;
    for (int d = 0; d < s.dimension; ++d) {
      const double hi = 0.5 * (g[d][p] + g[d][p + st[d]]), lo = 0.5 * (g[d][p] + g[d][p - st[d]]);
      const auto m = static_cast<std::size_t>(ijk[d]);
      sum += hi_w[d][m] * hi - lo_w[d][m] * lo;
    }
    div[q++] = sum;
  });
  return div;
}

VectorSolveStats solve_vector_poisson(Multigrid& mg, const VectorField& source_up, VectorPotentials& warm,
                                      VectorField& X_up, const SolveSettings& settings) {
  const GridShape& s = mg.shape();
  VectorSolveStats stats;
  const VectorField src = to_cartesian(mg, source_up);
  for (int a = 0; a < 3; ++a) {
    if (warm.B[a].size() != s.cells()) warm.B[a].assign(s.cells(), 0.0);
    if (!cartesian_component_active(s, a)) {
      std::fill(warm.B[a].begin(), warm.B[a].end(), 0.0);
      stats.component[a].converged = true;
      continue;
    }
    ScalarEquation eq = cartesian_component_equation(s, a);
    eq.s0 = src[a];
    stats.component[a] = mg.solve(eq, warm.B[a], settings);
  }
  const VectorField B_up = to_coordinate(mg, warm.B);
  ScalarEquation chi = chi_equation();
  chi.s0 = divergence(mg, B_up);
  stats.chi = mg.solve(chi, warm.chi, settings);
  // X^i = B^i - f^ii d_i chi / 4 (centred differences).
  const std::vector<double> gchi = mg.with_ghosts(chi, warm.chi);
  const auto st = mg.ghosted_strides();
  X_up = B_up;
  std::size_t q = 0;
  for_all_cells(s, 0, [&](int i, int j, int k) {
    const std::size_t p = static_cast<std::size_t>(mg.ghosted_index(i, j, k));
    const Point3& f = mg.frames().f[p];
    for (int d = 0; d < s.dimension; ++d)
      X_up[d][q] -= 0.25 * (gchi[p + st[d]] - gchi[p - st[d]]) / (2 * s.dx[d] * f[d]);
    ++q;
  });
  return stats;
}

}  // namespace remnant::xcfc
