#include "XCFC/xcfc_system.hpp"

#include <cmath>
#include <numbers>

namespace remnant::xcfc {
namespace {
constexpr double pi = std::numbers::pi;
constexpr int kPair[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};

template <class F>
void for_cells(const GridShape& s, F&& f) {
  std::size_t q = 0;
  for (int k = 0; k < s.n[2]; ++k)
    for (int j = 0; j < s.n[1]; ++j)
      for (int i = 0; i < s.n[0]; ++i) f(q++, i, j, k);
}

VectorField raise(const Multigrid& mg, const VectorField& dn, double factor) {
  const GridShape& s = mg.shape();
  VectorField up;
  for (auto& c : up) c.assign(s.cells(), 0.0);
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const Point3& f = mg.frames().f[static_cast<std::size_t>(mg.ghosted_index(i, j, k))];
    for (int c = 0; c < 3; ++c) up[c][q] = factor * dn[c][q] / f[c];
  });
  return up;
}
}  // namespace

std::vector<double> XcfcState::alpha() const {
  std::vector<double> a(psi.size());
  for (std::size_t q = 0; q < a.size(); ++q) a[q] = alpha_psi[q] / psi[q];
  return a;
}

ScalarEquation conformal_factor_equation() {
  ScalarEquation eq;
  eq.far_value = 1.0;
  return eq;
}
ScalarEquation lapse_equation() {
  ScalarEquation eq;
  eq.far_value = 1.0;
  return eq;
}

XcfcSolver::XcfcSolver(const GridShape& shape, MPI_Comm comm) : mg_(shape, comm) {}

void XcfcSolver::compute_A(XcfcState& st) {
  const GridShape& s = mg_.shape();
  const VectorField g = ghosted_coordinate_components(mg_, st.X);
  const auto stride = mg_.ghosted_strides();
  for (auto& a : st.A) a.assign(s.cells(), 0.0);
  st.A2.assign(s.cells(), 0.0);
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const std::size_t p = static_cast<std::size_t>(mg_.ghosted_index(i, j, k));
    const Point3& f = mg_.frames().f[p];
    const Christoffels G = coords::christoffels(s.coordinates, s.point(i, j, k));
    double X[3], D[3][3];  // D[a][b] = nabla_a X^b
    for (int b = 0; b < 3; ++b) X[b] = g[b][p];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        double d = s.used(a) ? (g[b][p + stride[a]] - g[b][p - stride[a]]) / (2 * s.dx[a]) : 0.0;
        for (int c = 0; c < 3; ++c) d += G[b][a][c] * X[c];
        D[a][b] = d;
      }
    const double div = D[0][0] + D[1][1] + D[2][2];
    double A2 = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) {
        double v = D[a][b] / f[a] + D[b][a] / f[b];
        if (a == b) v -= (2.0 / 3.0) * div / f[a];
        st.A[kPair[a][b]][q] = v;
        A2 += (a == b ? 1.0 : 2.0) * f[a] * f[b] * v * v;
      }
    st.A2[q] = A2;
  });
}

void XcfcSolver::solve_conformal_factor(const std::vector<double>& E, const VectorField& S_dn, XcfcState& st,
                                        XcfcStats& stats, const SolveSettings& settings) {
  const GridShape& s = mg_.shape();
  // The vector residuals are measured against the gravitational source scale 2 pi max E~ as well:
  // a nearly static star has momenta at round-off level, which need no relative accuracy.
  SolveSettings vset = settings;
  for (double e : E) vset.scale_floor = std::max(vset.scale_floor, 2 * pi * std::abs(e));
  stats.X = solve_vector_poisson(mg_, raise(mg_, S_dn, 8 * pi), st.X_potentials, st.X, vset);
  compute_A(st);
  ScalarEquation eq = conformal_factor_equation();
  eq.s1.resize(s.cells());
  eq.s7.resize(s.cells());
  for (std::size_t q = 0; q < s.cells(); ++q) {
    eq.s1[q] = -2 * pi * E[q];
    eq.s7[q] = -0.125 * st.A2[q];
  }
  if (st.psi.size() != s.cells()) st.psi.assign(s.cells(), 1.0);
  stats.psi = mg_.solve(eq, st.psi, settings);
}

double XcfcSolver::conformal_factor_residual(const std::vector<double>& E, const XcfcState& st) {
  const GridShape& s = mg_.shape();
  ScalarEquation eq = conformal_factor_equation();
  eq.s1.resize(s.cells());
  eq.s7.resize(s.cells());
  double scale = 0;
  for (std::size_t q = 0; q < s.cells(); ++q) {
    eq.s1[q] = -2 * pi * E[q];
    eq.s7[q] = st.A2.empty() ? 0.0 : -0.125 * st.A2[q];
    scale = std::max(scale, std::abs(eq.s1[q] / st.psi[q]) + std::abs(eq.s7[q] / std::pow(st.psi[q], 7)));
  }
  return mg_.residual_norm(eq, st.psi) / (scale > 0 ? scale : 1.0);
}

void XcfcSolver::solve_lapse_and_shift(const std::vector<double>& E, const VectorField& S_dn,
                                       const std::vector<double>& S_trace, XcfcState& st, XcfcStats& stats,
                                       const SolveSettings& settings) {
  const GridShape& s = mg_.shape();
  ScalarEquation eq = lapse_equation();
  eq.k.resize(s.cells());
  for (std::size_t q = 0; q < s.cells(); ++q) {
    const double psi = st.psi[q], p2 = psi * psi, p4 = p2 * p2;
    eq.k[q] = 2 * pi * (E[q] + 2 * S_trace[q]) / p2 + 0.875 * st.A2[q] / (p4 * p4);
  }
  if (st.alpha_psi.size() != s.cells()) st.alpha_psi = st.psi;
  stats.alpha_psi = mg_.solve(eq, st.alpha_psi, settings);

  // Shift source: 16 pi alpha psi^-6 f^ij S~_j + 2 A^ij d_j (alpha psi^-6).
  std::vector<double> w(s.cells());
  for (std::size_t q = 0; q < s.cells(); ++q) {
    const double p = st.psi[q], p2 = p * p, p4 = p2 * p2;
    w[q] = st.alpha_psi[q] / (p4 * p2 * p);
  }
  ScalarEquation weq;
  weq.far_value = 1.0;
  const std::vector<double> gw = mg_.with_ghosts(weq, w);
  const auto stride = mg_.ghosted_strides();
  VectorField src;
  for (auto& c : src) c.assign(s.cells(), 0.0);
  for_cells(s, [&](std::size_t q, int i, int j, int k) {
    const std::size_t p = static_cast<std::size_t>(mg_.ghosted_index(i, j, k));
    const Point3& f = mg_.frames().f[p];
    double dw[3] = {0, 0, 0};
    for (int d = 0; d < s.dimension; ++d) dw[d] = (gw[p + stride[d]] - gw[p - stride[d]]) / (2 * s.dx[d]);
    for (int a = 0; a < 3; ++a) {
      double v = 16 * pi * w[q] * S_dn[a][q] / f[a];
      for (int b = 0; b < 3; ++b) v += 2 * st.A[kPair[a][b]][q] * dw[b];
      src[a][q] = v;
    }
  });
  SolveSettings vset = settings;
  for (double e : E) vset.scale_floor = std::max(vset.scale_floor, 2 * pi * std::abs(e));
  stats.beta = solve_vector_poisson(mg_, src, st.beta_potentials, st.beta, vset);
}

}  // namespace remnant::xcfc
