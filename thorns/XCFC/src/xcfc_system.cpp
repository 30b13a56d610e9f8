#include "XCFC/xcfc_system.hpp"

#include <cmath>
#include <numbers>

namespace remnant::xcfc {
namespace {
constexpr double pi = std::numbers::pi;
constexpr int kPair[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};

// f(n, q) for every cell of every part.
template <class F>
void for_every_cell(const CompositeField& like, F&& f) {
  for (std::size_t n = 0; n < like.part.size(); ++n)
    for (std::size_t q = 0; q < like.part[n].size(); ++q) f(n, q);
}

// f(n, q) for this rank's share of the cells of every part (CellShare); the caller completes what
// it wrote (CompositeMultigrid::complete).
template <class F>
void for_shared_cells(const CompositeMultigrid& mg, F&& f) {
  for (int n = 0; n < mg.parts(); ++n)
    for_share_cells(mg, n, [&](std::size_t q, std::size_t, int, int, int) { f(static_cast<std::size_t>(n), q); });
}

double max_abs_times(const CompositeField& E, double factor) {
  double m = 0;
  for (const auto& part : E.part)
    for (double e : part) m = std::max(m, factor * std::abs(e));
  return m;
}

VectorField raise(const CompositeMultigrid& mg, const VectorField& dn, double factor) {
  VectorField up;
  for (auto& c : up) c = mg.field();
  for (int n = 0; n < mg.parts(); ++n) {
    const PartGeometry& g = mg.part(n);
    for_share_cells(mg, n, [&](std::size_t q, std::size_t p, int, int, int) {
      const Point3& f = g.frames().diagonal(p);
      for (int c = 0; c < 3; ++c) up[c].part[n][q] = factor * dn[c].part[n][q] / f[c];
    });
  }
  mg.complete({&up[0], &up[1], &up[2]});
  return up;
}
}  // namespace

CompositeField XcfcState::alpha() const {
  CompositeField a = psi;
  for_every_cell(a, [&](std::size_t n, std::size_t q) { a.part[n][q] = alpha_psi.part[n][q] / psi.part[n][q]; });
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

XcfcSolver::XcfcSolver(const GridShape& shape, MPI_Comm comm, MultigridStorage storage) : mg_(shape, comm, storage) {}
XcfcSolver::XcfcSolver(const CompositeLayout& layout, MPI_Comm comm, MultigridStorage storage)
    : mg_(layout, comm, storage) {}

const SolverGeometry& XcfcSolver::geometry() {
  if (!geometry_.current_for(mg_)) geometry_ = SolverGeometry(mg_);  // first use, or mg_ replaced
  return geometry_;
}

void XcfcSolver::compute_A(XcfcState& st) {
  const VectorField g = ghosted_coordinate_components(mg_, st.X);
  const SolverGeometry& geo = geometry();
  for (auto& a : st.A) a = mg_.field();
  st.A2 = mg_.field();
  for (int n = 0; n < mg_.parts(); ++n) {
    const PartGeometry& pg = mg_.part(n);
    const GridShape& s = pg.shape;
    const auto& stride = pg.strides;
    const std::vector<CompactChristoffels>& gamma = geo.christoffels(n);
    for_share_cells(mg_, n, [&](std::size_t q, std::size_t p, int, int, int) {
      const Point3& f = pg.frames().diagonal(p);
      // Cartesian parts store no symbols (all zero): the same arithmetic with zeros.
      static const CompactChristoffels flat{};
      const Christoffels G = expand(gamma.empty() ? flat : gamma[q]);
      double X[3], D[3][3];  // D[a][b] = nabla_a X^b
      for (int b = 0; b < 3; ++b) X[b] = g[b].part[n][p];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          double d = s.used(a) ? (g[b].part[n][p + stride[a]] - g[b].part[n][p - stride[a]]) / (2 * s.dx[a]) : 0.0;
          for (int c = 0; c < 3; ++c) d += G[b][a][c] * X[c];
          D[a][b] = d;
        }
      const double div = D[0][0] + D[1][1] + D[2][2];
      double A2 = 0;
      for (int a = 0; a < 3; ++a)
        for (int b = a; b < 3; ++b) {
          double v = D[a][b] / f[a] + D[b][a] / f[b];
          if (a == b) v -= (2.0 / 3.0) * div / f[a];
          st.A[kPair[a][b]].part[n][q] = v;
          A2 += (a == b ? 1.0 : 2.0) * f[a] * f[b] * v * v;
        }
      st.A2.part[n][q] = A2;
    });
  }
  mg_.complete({&st.A[0], &st.A[1], &st.A[2], &st.A[3], &st.A[4], &st.A[5], &st.A2});
}

void XcfcSolver::solve_conformal_factor(const CompositeField& E, const VectorField& S_dn, XcfcState& st,
                                        XcfcStats& stats, const SolveSettings& settings) {
  solve_vector_potential(E, S_dn, st, stats, settings);
  solve_psi(E, st, stats, settings);
}

void XcfcSolver::solve_vector_potential(const CompositeField& E, const VectorField& S_dn, XcfcState& st,
                                        XcfcStats& stats, const SolveSettings& settings) {
  // The vector residuals are measured against the gravitational source scale 2 pi max E~ as well:
  // a nearly static star has momenta at round-off level, which need no relative accuracy.
  SolveSettings vset = settings;
  vset.scale_floor = std::max(vset.scale_floor, max_abs_times(E, 2 * pi));
  stats.X = solve_vector_poisson(mg_, raise(mg_, S_dn, 8 * pi), st.X_potentials, st.X, vset);
  compute_A(st);
}

void XcfcSolver::solve_psi(const CompositeField& E, XcfcState& st, XcfcStats& stats, const SolveSettings& settings) {
  CompositeEquation eq;
  eq.boundary = conformal_factor_equation();
  eq.s1 = mg_.field();
  eq.s7 = mg_.field();
  for_shared_cells(mg_, [&](std::size_t n, std::size_t q) {
    eq.s1.part[n][q] = -2 * pi * E.part[n][q];
    eq.s7.part[n][q] = -0.125 * st.A2.part[n][q];
  });
  mg_.complete({&eq.s1, &eq.s7});
  if (st.psi.part.size() != eq.s1.part.size()) st.psi = mg_.field(1.0);
  stats.psi = mg_.solve(eq, st.psi, settings);
}

double XcfcSolver::conformal_factor_residual(const CompositeField& E, const XcfcState& st) {
  CompositeEquation eq;
  eq.boundary = conformal_factor_equation();
  eq.s1 = mg_.field();
  eq.s7 = mg_.field();
  double scale = 0;
  for_every_cell(eq.s1, [&](std::size_t n, std::size_t q) {
    const double psi = st.psi.part[n][q];
    eq.s1.part[n][q] = -2 * pi * E.part[n][q];
    eq.s7.part[n][q] = st.A2.empty() ? 0.0 : -0.125 * st.A2.part[n][q];
    scale = std::max(scale, std::abs(eq.s1.part[n][q] / psi) + std::abs(eq.s7.part[n][q] / std::pow(psi, 7)));
  });
  return mg_.residual_norm(eq, st.psi) / (scale > 0 ? scale : 1.0);
}

void XcfcSolver::solve_lapse_and_shift(const CompositeField& E, const VectorField& S_dn, const CompositeField& S_trace,
                                       XcfcState& st, XcfcStats& stats, const SolveSettings& settings) {
  solve_lapse(E, S_trace, st, stats, settings);
  solve_shift(E, S_dn, st, stats, settings);
}

void XcfcSolver::solve_lapse(const CompositeField& E, const CompositeField& S_trace, XcfcState& st, XcfcStats& stats,
                             const SolveSettings& settings) {
  CompositeEquation eq;
  eq.boundary = lapse_equation();
  eq.k = mg_.field();
  for_shared_cells(mg_, [&](std::size_t n, std::size_t q) {
    const double psi = st.psi.part[n][q], p2 = psi * psi, p4 = p2 * p2;
    eq.k.part[n][q] = 2 * pi * (E.part[n][q] + 2 * S_trace.part[n][q]) / p2 + 0.875 * st.A2.part[n][q] / (p4 * p4);
  });
  mg_.complete({&eq.k});
  if (st.alpha_psi.part.size() != eq.k.part.size()) st.alpha_psi = st.psi;
  stats.alpha_psi = mg_.solve(eq, st.alpha_psi, settings);
}

void XcfcSolver::solve_shift(const CompositeField& E, const VectorField& S_dn, XcfcState& st, XcfcStats& stats,
                             const SolveSettings& settings) {
  // Shift source: 16 pi alpha psi^-6 f^ij S~_j + 2 A^ij d_j (alpha psi^-6).
  CompositeField w = mg_.field();
  for_shared_cells(mg_, [&](std::size_t n, std::size_t q) {
    const double p = st.psi.part[n][q], p2 = p * p, p4 = p2 * p2;
    w.part[n][q] = st.alpha_psi.part[n][q] / (p4 * p2 * p);
  });
  mg_.complete({&w});
  ScalarEquation weq;
  weq.far_value = 1.0;
  const CompositeField gw = mg_.with_ghosts(weq, w, true);
  VectorField src;
  for (auto& c : src) c = mg_.field();
  for (int n = 0; n < mg_.parts(); ++n) {
    const PartGeometry& pg = mg_.part(n);
    const GridShape& s = pg.shape;
    const auto& stride = pg.strides;
    const auto& g = gw.part[n];
    for_share_cells(mg_, n, [&](std::size_t q, std::size_t p, int, int, int) {
      const Point3& f = pg.frames().diagonal(p);
      double dw[3] = {0, 0, 0};
      for (int d = 0; d < s.dimension; ++d) dw[d] = (g[p + stride[d]] - g[p - stride[d]]) / (2 * s.dx[d]);
      for (int a = 0; a < 3; ++a) {
        double v = 16 * pi * w.part[n][q] * S_dn[a].part[n][q] / f[a];
        for (int b = 0; b < 3; ++b) v += 2 * st.A[kPair[a][b]].part[n][q] * dw[b];
        src[a].part[n][q] = v;
      }
    });
  }
  mg_.complete({&src[0], &src[1], &src[2]});
  SolveSettings vset = settings;
  vset.scale_floor = std::max(vset.scale_floor, max_abs_times(E, 2 * pi));
  stats.beta = solve_vector_poisson(mg_, src, st.beta_potentials, st.beta, vset);
}

}  // namespace remnant::xcfc
