#include "line_relaxation.hpp"

#include <algorithm>
#include <cmath>

#include "level_ops.hpp"

namespace remnant::xcfc {
namespace {

// G lines of one colour at once (t, t + 2, ...): the Thomas recurrences are serial within a line,
// so interleaving independent lines hides their latency (each line's arithmetic is unchanged, so
// are its bits). Work arrays hold G entries per position along the line.
template <bool Factored, int G>
void pass_group(Level& L, const Lines& ln, const Ops& o, int t) {
  const int d = ln.d, n = ln.n;
  double* u = L.u.data();
  const double *alo = o.lo[d], *ahi = o.hi[d];
  const double *tlo = ln.e < 0 ? nullptr : o.lo[ln.e], *thi = ln.e < 0 ? nullptr : o.hi[ln.e];
  const double *c1lo = L.end_c1[d][0].data(), *c1hi = L.end_c1[d][1].data();
  const double *w = L.line_w[d].data(), *inv = L.line_inv[d].data();
  double *r = L.line_rhs.data(), *dd = L.line_di.data();
  const bool nonlinear = o.nonlinear();
  const std::ptrdiff_t pd = ln.pd, pe = ln.pe, qd = ln.qd;
  std::size_t q[G];
  std::ptrdiff_t p[G];
  int tg[G];
  double prev_r[G], prev_d[G], prev_up[G];
  for (int g = 0; g < G; ++g) {
    tg[g] = t + 2 * g, q[g] = ln.q0(tg[g]), p[g] = ln.p0(L, tg[g]);
    prev_r[g] = 0, prev_d[g] = 1, prev_up[g] = 0;  // prev_d: inverse pivot
  }
  // Right-hand sides and forward elimination in one pass.
  for (int m = 0; m < n; ++m) {
    for (int g = 0; g < G; ++g) {
      const std::size_t qq = q[g];
      const std::ptrdiff_t pp = p[g];
      const double u0 = u[pp];
      double b = o.f[qq];
      if (tlo) b -= tlo[qq] * u[pp - pe] + thi[qq] * u[pp + pe];
      if (m == 0) b -= alo[qq] * (u[pp - pd] - c1lo[tg[g]] * u0);
      if (m == n - 1) b -= ahi[qq] * (u[pp + pd] - c1hi[tg[g]] * u0);
      if constexpr (Factored) {
        b += o.s0[qq];
        prev_r[g] = b - w[qq] * prev_r[g];
      } else {
        double dR;
        b += o.source_and_derivative(qq, u0, dR) - dR * u0;
        double di = -o.diag[qq] - dR;
        if (m == 0) di += alo[qq] * c1lo[tg[g]];
        if (m == n - 1) di += ahi[qq] * c1hi[tg[g]];
        if (m > 0) {
          const double wm = alo[qq] * prev_d[g];
          di -= wm * prev_up[g];
          b -= wm * prev_r[g];
        }
        prev_r[g] = b, prev_d[g] = dd[m * G + g] = 1.0 / di, prev_up[g] = ahi[qq];
      }
      r[m * G + g] = prev_r[g];
      q[g] += static_cast<std::size_t>(qd), p[g] += pd;
    }
  }
  // Back substitution.
  double x[G];
  for (int g = 0; g < G; ++g) x[g] = 0;
  for (int m = n - 1; m >= 0; --m)
    for (int g = 0; g < G; ++g) {
      q[g] -= static_cast<std::size_t>(qd), p[g] -= pd;
      const std::size_t qq = q[g];
      if constexpr (Factored) {
        x[g] = (r[m * G + g] - ahi[qq] * x[g]) * inv[qq];
        u[p[g]] = x[g];
      } else {
        x[g] = (r[m * G + g] - ahi[qq] * x[g]) * dd[m * G + g];  // x = 0 at the last cell
        double un = x[g];
        if (nonlinear && !(un > 0.1 * u[p[g]])) un = 0.5 * u[p[g]];
        u[p[g]] = un;
      }
    }
}

template <bool Factored>
long long pass(Level& L, const Lines& ln, int colour, int t0, int t1) {
  constexpr int G = 4;
  const Ops o(L);
  const std::size_t need = static_cast<std::size_t>(G) * static_cast<std::size_t>(ln.n);
  if (L.line_rhs.size() < need) L.line_rhs.resize(need), L.line_di.resize(need);
  long long cells = 0;
  int t = t0 + ((colour - t0) & 1);
  for (; t + 2 * (G - 1) < t1; t += 2 * G, cells += static_cast<long long>(G) * ln.n) pass_group<Factored, G>(L, ln, o, t);
  for (; t < t1; t += 2, cells += ln.n) pass_group<Factored, 1>(L, ln, o, t);
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

long long factor_lines(Level& L, std::array<int, 2> t0, std::array<int, 2> t1) {
  const GridShape& s = L.shape;
  L.factored = false;
  long long cells = 0;
  if (s.dimension > 2 || !L.s1.empty() || !L.s7.empty()) return cells;
  for (int d = 0; d < s.dimension; ++d) {
    const Lines ln(L, d);
    const double *alo = L.a_lo[d].data(), *ahi = L.a_hi[d].data();
    const double *c1lo = L.end_c1[d][0].data(), *c1hi = L.end_c1[d][1].data();
    double *w = L.line_w[d].data(), *inv = L.line_inv[d].data();
    for (int t = std::max(0, t0[d]), end = std::min(ln.count, t1[d]); t < end; ++t, cells += ln.n) {
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
  return cells;
}

long long line_pass(Level& L, const Lines& ln, int colour, int t0, int t1) {
  return L.factored ? pass<true>(L, ln, colour, t0, t1) : pass<false>(L, ln, colour, t0, t1);
}

}  // namespace remnant::xcfc
