// Analysis::rotation: J, T/|W|, Omega_c, the Komar and proper masses and the m = 1, 2 density modes
// (definitions in rotation_diagnostics.hpp).
#include "Analysis/rotation_diagnostics.hpp"

#include <mpi.h>

#include <cmath>
#include <complex>
#include <limits>

#include "remnant/coordinates.hpp"
#include "remnant/domain.hpp"
#include "remnant/vars/Analysis.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::analysis {
namespace {

// Mirror planes through the rotation axis: a Cartesian reflect face at x = 0 maps phi to pi - phi,
// one at y = 0 maps phi to -phi (curvilinear grids reflect only at the equator).
struct AzimuthalMirrors {
  bool x = false, y = false;
  int images() const { return (x ? 2 : 1) * (y ? 2 : 1); }
  // Sum over the cell's images of e^{i m phi}.
  std::complex<double> sum(int m, double phi) const {
    const double c = std::cos(m * phi), s = std::sin(m * phi), sign = m % 2 == 0 ? 1.0 : -1.0;
    if (x && y) return {(1 + sign) * 2 * c, 0.0};
    if (y) return {2 * c, 0.0};
    if (x) return {(1 + sign) * c, (1 - sign) * s};  // e^{i m phi} + (-1)^m e^{-i m phi}
    return {c, s};
  }
};

AzimuthalMirrors mirrors(Context& ctx) {
  AzimuthalMirrors a;
  if (ctx.grid().coordinates() != CoordinateSystem::cartesian || ctx.grid().dimension() < 3) return a;
  const Domain d = ctx.grid().domain();
  for (int side = 0; side < 2; ++side) {
    const double xface = side == 0 ? d.lo[0] : d.hi[0], yface = side == 0 ? d.lo[1] : d.hi[1];
    a.x = a.x || (d.faces.boundary[0][side] == Boundary::reflect && xface == 0);
    a.y = a.y || (d.faces.boundary[1][side] == Boundary::reflect && yface == 0);
  }
  return a;
}

}  // namespace

RotationDiagnostics rotation_diagnostics(Context& ctx) {
  using Out = vars::Analysis::rotation_integrands;
  using Cons = vars::HydroBase::cons;
  using Prim = vars::HydroBase::prim;
  using Metric = vars::Spacetime::metric;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const bool modes = ctx.grid().dimension() == 3;
  const AzimuthalMirrors mirror = modes ? mirrors(ctx) : AzimuthalMirrors{};
  double r_min = inf, omega_centre = -inf;
  for (Block* b : ctx.grid().local_blocks()) {
    const Cons cons(ctx, *b);
    const Prim prim(ctx, *b);
    const Metric metric(ctx, *b);
    const Out out(ctx, *b);
    const CoordinateSystem cs = b->coordinates;
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 x{b->centroid(0, i), b->centroid(1, j), b->centroid(2, k)};
      const Point3 X = coords::to_cartesian(cs, x);
      const double varpi2 = X[0] * X[0] + X[1] * X[1];
      const Point3 killing = coords::vector_from_cartesian(cs, x, {-X[1], X[0], 0.0});
      const Point3 v{prim.vel(0, i, j, k), prim.vel(1, i, j, k), prim.vel(2, i, j, k)};
      const Point3 beta{metric.beta(0, i, j, k), metric.beta(1, i, j, k), metric.beta(2, i, j, k)};
      double S_phi = 0, S_v = 0, S_beta = 0;
      for (int c = 0; c < 3; ++c) {
        const double S = cons.S(c, i, j, k);
        S_phi += S * killing[c];
        S_v += S * v[c];
        S_beta += S * beta[c];
      }
      // u^phi / u^t from the Cartesian components: (X V_y - Y V_x) / varpi^2.
      const Point3 V = coords::vector_to_cartesian(cs, x, v), B = coords::vector_to_cartesian(cs, x, beta);
      const double alpha = metric.alpha(i, j, k), psi = metric.psi(i, j, k);
      const double omega = varpi2 > 0 ? (alpha * (X[0] * V[1] - X[1] * V[0]) - (X[0] * B[1] - X[1] * B[0])) / varpi2 : 0.0;
      const double D = cons.D(i, j, k), psi6 = std::pow(psi, 6);
      const double E = cons.tau(i, j, k) + D, S_trace = S_v + 3 * psi6 * prim.press(i, j, k);
      out.J(i, j, k) = S_phi;
      out.M_komar(i, j, k) = alpha * (E + S_trace) - 2 * S_beta;
      out.M_proper(i, j, k) = D * (1 + prim.eps(i, j, k));
      out.T_kin(i, j, k) = 0.5 * omega * S_phi;
      const double phi = std::atan2(X[1], X[0]);
      const std::complex<double> e1 = modes ? mirror.sum(1, phi) : 0.0, e2 = modes ? mirror.sum(2, phi) : 0.0;
      out.re1(i, j, k) = D * e1.real(), out.im1(i, j, k) = D * e1.imag();
      out.re2(i, j, k) = D * e2.real(), out.im2(i, j, k) = D * e2.imag();
      // The cell nearest the origin, ties to the largest value (as rho_c).
      const double r = std::sqrt(varpi2 + X[2] * X[2]);
      if (r < r_min) r_min = r, omega_centre = omega;
      else if (r == r_min) omega_centre = std::max(omega_centre, omega);
    });
  }
  MPI_Comm comm = ctx.grid().comm();
  double r_global, omega_global;
  MPI_Allreduce(&r_min, &r_global, 1, MPI_DOUBLE, MPI_MIN, comm);
  const double mine = r_min == r_global ? omega_centre : -inf;
  MPI_Allreduce(&mine, &omega_global, 1, MPI_DOUBLE, MPI_MAX, comm);
  const int out = Out::id(ctx);
  ctx.check_access(out);
  auto integral = [&](int comp) { return ctx.grid().reduce(out, comp, ReductionKind::volume_integral); };
  RotationDiagnostics d;
  d.J = integral(Out::idx::J);
  d.M_komar = integral(Out::idx::M_komar);
  d.M_proper = integral(Out::idx::M_proper);
  d.T_kin = integral(Out::idx::T_kin);
  const double W = d.M_proper + d.T_kin - d.M_komar;
  d.T_over_W = W != 0 ? d.T_kin / std::abs(W) : 0.0;
  d.omega_c = omega_global;
  if (modes) {
    const int cons = Cons::id(ctx);
    const double mass = mirror.images() * ctx.grid().reduce(cons, Cons::idx::D, ReductionKind::volume_integral);
    if (mass > 0) {
      d.mode_m1 = std::hypot(integral(Out::idx::re1), integral(Out::idx::im1)) / mass;
      d.mode_m2 = std::hypot(integral(Out::idx::re2), integral(Out::idx::im2)) / mass;
    }
  }
  return d;
}

}  // namespace remnant::analysis
