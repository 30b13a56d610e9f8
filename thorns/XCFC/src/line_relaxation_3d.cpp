#include "line_relaxation_3d.hpp"

#include <cmath>

#include "level_ops.hpp"

namespace remnant::xcfc {
namespace {

// Thomas algorithm for a[m] x[m-1] + b[m] x[m] + c[m] x[m+1] = r[m] (a[0] and c[n-1] unused): the
// solution replaces r, b is overwritten by the inverse pivots (one division per row).
void thomas(int n, const double* a, double* b, const double* c, double* r) {
  b[0] = 1.0 / b[0];
  for (int m = 1; m < n; ++m) {
    const double w = a[m] * b[m - 1];
    b[m] = 1.0 / (b[m] - w * c[m - 1]);
    r[m] -= w * r[m - 1];
  }
  r[n - 1] *= b[n - 1];
  for (int m = n - 2; m >= 0; --m) r[m] = (r[m] - c[m] * r[m + 1]) * b[m];
}

// The cyclic system (row 0 couples x[n-1] by a[0], row n-1 couples x[0] by c[n-1]), n >= 3, by
// Sherman-Morrison: two Thomas solves of the tridiagonal part with corrected corner pivots.
void cyclic_thomas(int n, const double* a, double* b, const double* c, double* r, double* z, double* b2) {
  const double gamma = -b[0], beta = a[0], alpha = c[n - 1];
  b[0] -= gamma;
  b[n - 1] -= alpha * beta / gamma;
  for (int m = 0; m < n; ++m) b2[m] = b[m], z[m] = 0.0;
  z[0] = gamma, z[n - 1] = alpha;
  thomas(n, a, b, c, r);
  thomas(n, a, b2, c, z);
  const double fact = (r[0] + beta * r[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
  for (int m = 0; m < n; ++m) r[m] -= fact * z[m];
}

// The line's end ghost as c0 + c1 u_end: c1 of the face (c0 is the current ghost's remainder).
double end_factor(const Level& L, const ScalarEquation& eq, int d, int side, std::size_t face_index) {
  switch (L.shape.boundary[d][side]) {
    case Boundary::outer:
      if (eq.dirichlet) return -1.0;
      if (eq.falloff == 1.0) return L.robin1[d][side][face_index];
      if (eq.falloff == 2.0) return L.robin2[d][side][face_index];
      return std::pow(L.robin1[d][side][face_index], eq.falloff);
    case Boundary::reflect: return eq.parity[d][side];  // the mirror is the end cell itself
    default: return 0.0;  // axis, origin (another line's cell, behind a face of zero area), interface
  }
}

}  // namespace

long long line_pass_3d(Level& L, const ScalarEquation& eq, int d, int colour) {
  const GridShape& s = L.shape;
  const int e1 = (d + 1) % 3, e2 = (d + 2) % 3, n = s.n[d];
  const Ops o(L);
  double* u = L.u.data();
  const std::ptrdiff_t pd = L.st[d], pe1 = L.st[e1], pe2 = L.st[e2];
  const std::size_t qd = d == 0 ? 1 : d == 1 ? static_cast<std::size_t>(s.n[0]) : static_cast<std::size_t>(s.n[0]) * s.n[1];
  const bool cyclic = s.boundary[d][0] == Boundary::periodic && n >= 3;
  const bool nonlinear = o.nonlinear();
  const double *alo = o.lo[d], *ahi = o.hi[d], *lo1 = o.lo[e1], *hi1 = o.hi[e1], *lo2 = o.lo[e2], *hi2 = o.hi[e2];
  const auto nn = static_cast<std::size_t>(n);
  L.line_scratch.resize(6 * nn);
  double *a = L.line_scratch.data(), *b = a + nn, *c = b + nn, *r = c + nn, *z = r + nn, *b2 = z + nn;
  long long cells = 0;
  for (int t2 = 0; t2 < s.n[e2]; ++t2)
    for (int t1 = 0; t1 < s.n[e1]; ++t1) {
      if (((t1 + t2) & 1) != colour) continue;
      std::array<int, 3> ijk{};
      ijk[e1] = t1, ijk[e2] = t2;
      const std::size_t q0 = L.cell(ijk[0], ijk[1], ijk[2]);
      const std::ptrdiff_t p0 = L.at(ijk[0], ijk[1], ijk[2]);
      const std::size_t face = static_cast<std::size_t>(t1) + static_cast<std::size_t>(s.n[e1]) * static_cast<std::size_t>(t2);
      for (int m = 0; m < n; ++m) {
        const std::size_t q = q0 + static_cast<std::size_t>(m) * qd;
        const std::ptrdiff_t p = p0 + m * pd;
        const double u0 = u[p];
        double dR;
        double rhs = o.f[q] - (lo1[q] * u[p - pe1] + hi1[q] * u[p + pe1] + lo2[q] * u[p - pe2] + hi2[q] * u[p + pe2]);
        rhs += o.source_and_derivative(q, u0, dR) - dR * u0;
        double di = -o.diag[q] - dR;
        a[m] = alo[q], c[m] = ahi[q];
        if (!cyclic && m == 0) {
          const double c1 = end_factor(L, eq, d, 0, face);
          rhs -= a[m] * (u[p - pd] - c1 * u0), di += a[m] * c1, a[m] = 0.0;
        }
        if (!cyclic && m == n - 1) {
          const double c1 = end_factor(L, eq, d, 1, face);
          rhs -= c[m] * (u[p + pd] - c1 * u0), di += c[m] * c1, c[m] = 0.0;
        }
        b[m] = di, r[m] = rhs;
      }
      if (cyclic) cyclic_thomas(n, a, b, c, r, z, b2);
      else thomas(n, a, b, c, r);
      for (int m = 0; m < n; ++m) {
        double& um = u[p0 + m * pd];
        double un = r[m];
        if (nonlinear && !(un > 0.1 * um)) un = 0.5 * um;
        um = un;
      }
      cells += n;
    }
  return cells;
}

}  // namespace remnant::xcfc
