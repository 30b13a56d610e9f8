#include "line_relaxation.hpp"

#include <cmath>

#include "level_ops.hpp"

namespace remnant::xcfc {
namespace {

template <bool Factored>
long long pass(Level& L, const Lines& ln, int colour, int t0, int t1) {
  const Ops o(L);
  const int d = ln.d, n = ln.n;
  double* u = L.u.data();
  const double *alo = o.lo[d], *ahi = o.hi[d];
  const double *tlo = ln.e < 0 ? nullptr : o.lo[ln.e], *thi = ln.e < 0 ? nullptr : o.hi[ln.e];
  const double *c1lo = L.end_c1[d][0].data(), *c1hi = L.end_c1[d][1].data();
  const double *w = L.line_w[d].data(), *inv = L.line_inv[d].data();
  double *r = L.line_rhs.data(), *dd = L.line_di.data();
  const bool nonlinear = o.nonlinear();
  const std::ptrdiff_t pd = ln.pd, pe = ln.pe, qd = ln.qd;
  long long cells = 0;
  for (int t = t0 + ((colour - t0) & 1); t < t1; t += 2, cells += n) {
    const std::size_t q0 = ln.q0(t);
    const std::ptrdiff_t p0 = ln.p0(L, t);
    // Right-hand sides and forward elimination in one pass.
    double prev_r = 0, prev_d = 1, prev_up = 0;  // prev_d: inverse pivot
    std::size_t q = q0;
    std::ptrdiff_t p = p0;
    for (int m = 0; m < n; ++m, q += static_cast<std::size_t>(qd), p += pd) {
      const double u0 = u[p];
      double b = o.f[q];
      if (tlo) b -= tlo[q] * u[p - pe] + thi[q] * u[p + pe];
      if (m == 0) b -= alo[q] * (u[p - pd] - c1lo[t] * u0);
      if (m == n - 1) b -= ahi[q] * (u[p + pd] - c1hi[t] * u0);
      if constexpr (Factored) {
        b += o.s0[q];
        prev_r = b - w[q] * prev_r;
      } else {
        double dR;
        b += o.source_and_derivative(q, u0, dR) - dR * u0;
        double di = -o.diag[q] - dR;
        if (m == 0) di += alo[q] * c1lo[t];
        if (m == n - 1) di += ahi[q] * c1hi[t];
        if (m > 0) {
          const double wm = alo[q] * prev_d;
          di -= wm * prev_up;
          b -= wm * prev_r;
        }
        prev_r = b, prev_d = dd[m] = 1.0 / di, prev_up = ahi[q];
      }
      r[m] = prev_r;
    }
    // Back substitution.
    double x = 0;
    for (int m = n - 1; m >= 0; --m) {
      q -= static_cast<std::size_t>(qd), p -= pd;
      if constexpr (Factored) {
        x = (r[m] - ahi[q] * x) * inv[q];
        u[p] = x;
      } else {
        x = (r[m] - ahi[q] * x) * dd[m];  // x = 0 at the last cell
        double un = x;
        if (nonlinear && !(un > 0.1 * u[p])) un = 0.5 * u[p];
        u[p] = un;
      }
    }
  }
  return cells;
}

}  // namespace

void set_line_ends(Level& L, const ScalarEquation& eq) {
  const GridShape& s = L.shape;
  if (s.dimension > 2) return;
  for (int d = 0; d < s.dimension; ++d) {
    const Lines ln(L, d);
    for (int side = 0; side < 2; ++side) {
      const Boundary bc = s.boundary[d][side];
      for (int t = 0; t < ln.count; ++t) {
        double c1 = eq.parity[d][side];
        if (bc == Boundary::outer) {
          const double ratio = L.robin1[d][side][static_cast<std::size_t>(t)];
          c1 = eq.dirichlet        ? -1.0
               : eq.falloff == 1.0 ? ratio
               : eq.falloff == 2.0 ? L.robin2[d][side][static_cast<std::size_t>(t)]
                                   : std::pow(ratio, eq.falloff);
        } else if (bc == Boundary::interface || (bc == Boundary::origin && s.used(1) && s.origin_flips_theta())) {
          c1 = 0.0;  // a patch interface, or the mirror cell lies on another line: the ghost is held
        }
        L.end_c1[d][side][static_cast<std::size_t>(t)] = c1;
      }
    }
  }
}

void factor_lines(Level& L) {
  const GridShape& s = L.shape;
  L.factored = false;
  if (s.dimension > 2 || !L.s1.empty() || !L.s7.empty()) return;
  for (int d = 0; d < s.dimension; ++d) {
    const Lines ln(L, d);
    const double *alo = L.a_lo[d].data(), *ahi = L.a_hi[d].data();
    const double *c1lo = L.end_c1[d][0].data(), *c1hi = L.end_c1[d][1].data();
    double *w = L.line_w[d].data(), *inv = L.line_inv[d].data();
    for (int t = 0; t < ln.count; ++t) {
      std::size_t q = ln.q0(t);
      double prev_inv = 0, prev_up = 0;
      for (int m = 0; m < ln.n; ++m, q += static_cast<std::size_t>(ln.qd)) {
        double di = -L.diagonal[q] - L.k[q];
        if (m == 0) di += alo[q] * c1lo[t];
        if (m == ln.n - 1) di += ahi[q] * c1hi[t];
        const double wm = m == 0 ? 0.0 : alo[q] * prev_inv;
        di -= wm * prev_up;
        w[q] = wm;
        inv[q] = prev_inv = 1.0 / di;
        prev_up = ahi[q];
      }
    }
  }
  L.factored = true;
}

long long line_pass(Level& L, const Lines& ln, int colour, int t0, int t1) {
  return L.factored ? pass<true>(L, ln, colour, t0, t1) : pass<false>(L, ln, colour, t0, t1);
}

}  // namespace remnant::xcfc
