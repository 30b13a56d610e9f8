#pragma once
// Well-balanced pressure for isentropic equilibria (GRMHD::well_balanced = isentropic; issue 15).
// A static ideal-gas star holds h alpha = const and K = p / rho^Gamma = const. The plain scheme
// balances the flux divergence of alpha psi^6 p (reconstructed p, interpolated metric) against point
// sources (-e d alpha + 6 alpha p d psi / psi, centred differences) only to O(dx^2), and differently
// along each direction: the residual force has a curl, which in an isentropic (neutrally stratified)
// star nothing opposes, so a meridional flow grows linearly in time (BU0, 64^2: |v| ~ 1e-4 by 1 ms,
// squeezing a poloidal field towards the axis). Here, in the manner of Kaeppeli & Mishra 2014:
//  - faces: h alpha (cell alpha) and K are reconstructed instead of rho and p, and the face rho, p
//    follow from the isentrope through (h = (h alpha)_face / alpha_face, K_face);
//  - sources: the static pressure part of the momentum source of cell i (what the plain source holds
//    at v = 0: -(rho h - p) d alpha + 6 alpha p d psi / psi, and alpha p dA / V in curvilinear
//    coordinates) is replaced by the flux divergence of cell i's own equilibrium pressure
//    p_i(alpha) = p(h = (h alpha)_i / alpha, K_i) at its two faces, with the faces' metric and areas.
// Consistent to O(dx^2) for any state, and exact (round-off) for data with h alpha and K constant;
// what a metric that is not exactly the matter's (XCFC's discrete solution) leaves is the discrete
// gradient of ln(h alpha): an acoustic readjustment, not a circulation. Ideal gas only (the isentrope
// in closed form). Where the equilibrium's h - 1 leaves a factor 2 of the plain state's (the
// atmosphere, the cell or two at a star's surface; IdealIsentrope::close), a face side keeps its
// plain state and a cell its plain sources.
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "GRMHD/reconstruction.hpp"
#include "line_scratch.hpp"

namespace remnant::grmhd {

// rho and p on the ideal-gas isentrope p = K rho^Gamma at specific enthalpy h (h = 1 + Gamma / (Gamma - 1) p / rho).
struct IdealIsentrope {
  double gamma = 2.0;
  // False (rho, p untouched) where h <= 1 or K <= 0 or the result is not finite.
  bool state(double h, double K, double& rho, double& p) const {
    const double x = (h - 1.0) * (gamma - 1.0) / (gamma * K);
    if (!(x > 0.0) || !(K > 0.0)) return false;
    const double r = gamma == 2.0 ? x : std::pow(x, 1.0 / (gamma - 1.0));
    const double pr = K * (gamma == 2.0 ? r * r : std::pow(r, gamma));
    if (!std::isfinite(r) || !std::isfinite(pr)) return false;
    rho = r;
    p = pr;
    return true;
  }
  double enthalpy(double rho, double p) const { return 1.0 + gamma / (gamma - 1.0) * p / rho; }
  // The equilibrium is trusted where its h - 1 stays within a factor 2 of the plain state's (h_ref):
  // in the atmosphere (h - 1 ~ 1e-8) a lapse change of 1e-3 across a cell would turn it into a
  // dense fluid, and near the surface the isentrope leaves the star within a cell.
  static bool close(double h, double h_ref) {
    const double a = h - 1.0, r = h_ref - 1.0;
    return a >= 0.5 * r && a <= 2.0 * r;
  }
  // state() where close(h, h_ref).
  bool state_near(double h, double h_ref, double K, double& rho, double& p) const {
    return close(h, h_ref) && state(h, K, rho, p);
  }
  double entropy(double rho, double p) const { return p / (gamma == 2.0 ? rho * rho : std::pow(rho, gamma)); }
};

// Line buffers of h alpha and K (cells with ghosts) and their face states.
struct WellBalancedLine {
  int cap = 0;
  std::vector<double> storage;
  double *q = nullptr, *K = nullptr, *qL = nullptr, *qR = nullptr, *KL = nullptr, *KR = nullptr, *scratch = nullptr;
  void ensure(int n, int ng) {
    const int len = n + 2 * ng + 4;
    if (len <= cap) return;
    cap = len;
    storage.assign(static_cast<std::size_t>(7 * len), 0.0);
    double* p = storage.data();
    auto take = [&](int offset) {
      double* a = p + offset;
      p += len;
      return a;
    };
    q = take(ng + 1);
    K = take(ng + 1);
    qL = take(1);
    qR = take(1);
    KL = take(1);
    KR = take(1);
    scratch = take(1);
  }
};

// The face value of the metric a (cell 0 of a line, stride s) at face f (between cells f - 1 and f),
// with the operations of set_face_metric.
inline double metric_face(MetricFaceInterpolation m, const double* a, std::ptrdiff_t s, int f) {
  if (m == MetricFaceInterpolation::cubic)
    return (9.0 * (a[(f - 1) * s] + a[f * s]) - (a[(f - 2) * s] + a[(f + 1) * s])) * (1.0 / 16.0);
  return 0.5 * (a[(f - 1) * s] + a[f * s]);
}

// Whether cell m of a line (rho, p, cell lapse alpha; a: the line's lapse, stride s) is in the
// well-balanced region: its own equilibrium is close (IdealIsentrope::close) at both its faces. A
// face is treated well-balanced only between two such cells on one isentrope (same_isentrope), and
// a cell's sources only where it and both neighbours are: the switch to the plain scheme at a surface is the same in both passes
// and never leaves a face with one balanced and one plain side.
inline bool equilibrium_cell(const IdealIsentrope& is, MetricFaceInterpolation faces, double rho, double p,
                             const double* a, std::ptrdiff_t s, int m) {
  const double h = is.enthalpy(rho, p), q = h * a[m * s];
  const double hm = q / metric_face(faces, a, s, m), hp = q / metric_face(faces, a, s, m + 1);
  return IdealIsentrope::close(hm, h) && IdealIsentrope::close(hp, h) && is.entropy(rho, p) > 0.0;
}

// Whether two neighbouring cells lie on one isentrope (K within a factor 2): the equilibrium has a
// single K, and h alone does not say so: hot, diluted cells just outside a star (h - 1 ~ 0.1-1, K
// orders above the star's) pass IdealIsentrope::close, and balancing them against a star cell made
// the 3D octant's surface cells D < 0 or eps ~ 1e3 (issue 15). Faces and sources use the plain
// scheme across such a jump.
inline bool same_isentrope(const IdealIsentrope& is, double rho_a, double p_a, double rho_b, double p_b) {
  const double ka = is.entropy(rho_a, p_a), kb = is.entropy(rho_b, p_b);
  return ka <= 2.0 * kb && kb <= 2.0 * ka;
}

// After the plain reconstruction and set_face_metric of an ideal-gas line (thermal slot = p): the face
// rho and p of both sides from the reconstructed h alpha and K. alpha: the metric's lapse at the
// line's cell 0, stride `stride`.
template <int NumRec, int NumFlux, class Stride>
inline void well_balanced_faces(const IdealIsentrope& is, Reconstruction rec, MetricFaceInterpolation faces,
                                const double* alpha, Stride stride, int n, int ng, LineScratch<NumRec, NumFlux>& L) {
  thread_local WellBalancedLine w;
  w.ensure(n, ng);
  const double* rho = L.cell[kRecRho];
  const double* p = L.cell[kRecThermal];
  for (int m = -ng; m < n + ng; ++m) {
    w.q[m] = is.enthalpy(rho[m], p[m]) * alpha[m * static_cast<std::ptrdiff_t>(stride)];
    w.K[m] = is.entropy(rho[m], p[m]);
  }
  const std::span<double> scratch(w.scratch, static_cast<std::size_t>(w.cap - 1));
  reconstruct(rec, w.q, w.qL, w.qR, n, scratch);
  reconstruct(rec, w.K, w.KL, w.KR, n, scratch);
  const std::ptrdiff_t s = stride;
  bool lower = equilibrium_cell(is, faces, rho[-1], p[-1], alpha, s, -1);
  for (int f = 0; f <= n; ++f) {
    const bool upper = equilibrium_cell(is, faces, rho[f], p[f], alpha, s, f);
    const bool both = lower && upper && same_isentrope(is, rho[f - 1], p[f - 1], rho[f], p[f]);
    lower = upper;
    if (!both) continue;
    const double inv_alpha = 1.0 / L.face.alpha[f];
    double rl, pl, rr, pr;
    if (is.state_near(w.qL[f] * inv_alpha, is.enthalpy(L.left[kRecRho][f], L.left[kRecThermal][f]), w.KL[f], rl, pl) &&
        is.state_near(w.qR[f] * inv_alpha, is.enthalpy(L.right[kRecRho][f], L.right[kRecThermal][f]), w.KR[f], rr, pr)) {
      L.left[kRecRho][f] = rl;
      L.left[kRecThermal][f] = pl;
      L.right[kRecRho][f] = rr;
      L.right[kRecThermal][f] = pr;
    }
  }
}

// The metric at the two faces of a cell along a line (a: the cell's value, s: the stride), with the
// operations of set_face_metric.
struct FaceLapsePsi6 {
  double alpha_minus, alpha_plus, psi6_minus, psi6_plus;
};
inline FaceLapsePsi6 cell_face_metric(MetricFaceInterpolation m, const double* alpha, const double* psi,
                                      std::ptrdiff_t s) {
  auto psi6 = [](double ps) {
    const double p2 = ps * ps;
    return p2 * p2 * p2;
  };
  return {metric_face(m, alpha, s, 0), metric_face(m, alpha, s, 1), psi6(metric_face(m, psi, s, 0)),
          psi6(metric_face(m, psi, s, 1))};
}

// What pass 2 needs to replace the static pressure sources (rhs.cpp).
struct WellBalancedSources {
  bool on = false;
  MetricFaceInterpolation faces = MetricFaceInterpolation::linear;
  IdealIsentrope isentrope;
};

}  // namespace remnant::grmhd
