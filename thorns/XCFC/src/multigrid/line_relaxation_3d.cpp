#include "line_relaxation_3d.hpp"

#include <array>
#include <cmath>
#include <tuple>
#include <utility>

#include "level_ops.hpp"

namespace remnant::xcfc {

void thomas_factor(int n, const double* a, double* b, const double* c) {
  b[0] = 1.0 / b[0];
  for (int m = 1; m < n; ++m) b[m] = 1.0 / (b[m] - a[m] * b[m - 1] * c[m - 1]);
}

void thomas_solve(int n, const double* a, const double* b, const double* c, double* r) {
  for (int m = 1; m < n; ++m) r[m] -= a[m] * b[m - 1] * r[m - 1];
  r[n - 1] *= b[n - 1];
  for (int m = n - 2; m >= 0; --m) r[m] = (r[m] - c[m] * r[m + 1]) * b[m];
}

double line_end_factor(const Level& L, const ScalarEquation& eq, int d, int side, std::size_t face_index) {
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

namespace {

// The cyclic system (row 0 couples x[n-1] by a[0], row n-1 couples x[0] by c[n-1]), n >= 3, by
// Sherman-Morrison: the tridiagonal part with corrected corner pivots, factorised once and solved
// for r and for the corner vector z.
void cyclic_thomas(int n, const double* a, double* b, const double* c, double* r, double* z) {
  const double gamma = -b[0], beta = a[0], alpha = c[n - 1];
  b[0] -= gamma;
  b[n - 1] -= alpha * beta / gamma;
  for (int m = 0; m < n; ++m) z[m] = 0.0;
  z[0] = gamma, z[n - 1] = alpha;
  thomas_factor(n, a, b, c);
  thomas_solve(n, a, b, c, r);
  thomas_solve(n, a, b, c, z);
  const double fact = (r[0] + beta * r[n - 1] / gamma) / (1.0 + z[0] + beta * z[n - 1] / gamma);
  for (int m = 0; m < n; ++m) r[m] -= fact * z[m];
}

// Line geometry along d: the transverse directions, strides and the cyclic flag.
struct Lines3 {
  int d, e1, e2, n;
  std::ptrdiff_t pd, pe1, pe2;
  std::size_t qd;
  bool cyclic;
  Lines3(const Level& L, int dir) : d(dir), e1((dir + 1) % 3), e2((dir + 2) % 3), n(L.shape.n[dir]) {
    const GridShape& s = L.shape;
    pd = L.st[d], pe1 = L.st[e1], pe2 = L.st[e2];
    qd = d == 0 ? 1 : d == 1 ? static_cast<std::size_t>(s.n[0]) : static_cast<std::size_t>(s.n[0]) * s.n[1];
    cyclic = s.boundary[d][0] == Boundary::periodic && n >= 3;
  }
  // The first cell of line (t1, t2): interior and ghosted offsets.
  std::pair<std::size_t, std::ptrdiff_t> start(const Level& L, int t1, int t2) const {
    std::array<int, 3> ijk{};
    ijk[e1] = t1, ijk[e2] = t2;
    return {L.cell(ijk[0], ijk[1], ijk[2]), L.at(ijk[0], ijk[1], ijk[2])};
  }
  // The line's index t1 + n_e1 t2, which is also its end cells' index on the faces across d.
  std::size_t line(const Level& L, int t1, int t2) const {
    return static_cast<std::size_t>(t1) + static_cast<std::size_t>(L.shape.n[e1]) * static_cast<std::size_t>(t2);
  }
};

// Linear equations: the line matrices are fixed, so their elimination is done once per solve and
// a pass is substitutions only (as in 2D). Cyclic lines keep the corrected tridiagonal part's
// factors, its solution z for the corner vector and, per line, beta/gamma and the denominator.
void factor_line(Level& L, const Lines3& ln, std::size_t q0, std::size_t line, const ScalarEquation& eq) {
  const int n = ln.n;
  const Ops o(L);
  double* w = L.line_w[ln.d].data();
  double* inv = L.line_inv[ln.d].data();
  const double *alo = o.lo[ln.d], *ahi = o.hi[ln.d];
  auto q_of = [&](int m) { return q0 + static_cast<std::size_t>(m) * ln.qd; };
  auto diag = [&](int m) { return -o.diag[q_of(m)] - o.k[q_of(m)]; };
  double b0 = diag(0), bn = diag(n - 1), gamma = 0, alpha = 0, beta = 0;
  if (ln.cyclic) {
    gamma = -b0, beta = alo[q_of(0)], alpha = ahi[q_of(n - 1)];
    b0 -= gamma;
    bn -= alpha * beta / gamma;
  } else {
    const double c1lo = line_end_factor(L, eq, ln.d, 0, line), c1hi = line_end_factor(L, eq, ln.d, 1, line);
    L.end_c1[ln.d][0][line] = c1lo, L.end_c1[ln.d][1][line] = c1hi;
    b0 += alo[q_of(0)] * c1lo;
    bn += ahi[q_of(n - 1)] * c1hi;
  }
  double prev_inv = 0, prev_up = 0;
  for (int m = 0; m < n; ++m) {
    const std::size_t q = q_of(m);
    double b = m == 0 ? b0 : m == n - 1 ? bn : diag(m);
    if (n == 1) b = b0 + (bn - diag(0));
    const double wm = m == 0 ? 0.0 : alo[q] * prev_inv;
    b -= wm * prev_up;
    w[q] = wm, inv[q] = prev_inv = 1.0 / b, prev_up = ahi[q];
  }
  if (!ln.cyclic) return;
  // z = T'^-1 (gamma, 0, ..., 0, alpha) with the factors just made.
  double* z = L.line_z.data();
  double r = 0;
  for (int m = 0; m < n; ++m) {
    const std::size_t q = q_of(m);
    const double rhs = m == 0 ? gamma : m == n - 1 ? alpha : 0.0;
    r = rhs - w[q] * r;
    z[q] = r;
  }
  double x = 0;
  for (int m = n - 1; m >= 0; --m) {
    const std::size_t q = q_of(m);
    x = (z[q] - ahi[q] * (m == n - 1 ? 0.0 : x)) * inv[q];
    z[q] = x;
  }
  L.line_cyclic[2 * line] = beta / gamma;
  L.line_cyclic[2 * line + 1] = 1.0 + z[q_of(0)] + beta / gamma * z[q_of(n - 1)];
}

// G lines of a linear equation at once with the factors of factor_lines_3d: lines t1, t1 + 2, ...
// of one row are independent, and interleaving them hides the latency of the serial recurrences
// and, for the strided theta and phi lines, uses each cache line of u and the coefficients G times
// (each line's arithmetic is unchanged, so are the bits).
template <int G>
void factored_group(Level& L, const Lines3& ln, const Ops& o, const std::size_t* line, const std::size_t* q0,
                    const std::ptrdiff_t* p0, double* r) {
  double* u = L.u.data();
  const int n = ln.n;
  const double *alo = o.lo[ln.d], *ahi = o.hi[ln.d], *lo1 = o.lo[ln.e1], *hi1 = o.hi[ln.e1], *lo2 = o.lo[ln.e2],
               *hi2 = o.hi[ln.e2];
  const double *w = L.line_w[ln.d].data(), *inv = L.line_inv[ln.d].data();
  const double *c1lo = L.end_c1[ln.d][0].data(), *c1hi = L.end_c1[ln.d][1].data();
  double prev[G] = {};
  for (int m = 0; m < n; ++m)
    for (int g = 0; g < G; ++g) {
      const std::size_t q = q0[g] + static_cast<std::size_t>(m) * ln.qd;
      const std::ptrdiff_t p = p0[g] + m * ln.pd;
      double rhs = o.f[q] + o.s0[q] - (lo1[q] * u[p - ln.pe1] + hi1[q] * u[p + ln.pe1] + lo2[q] * u[p - ln.pe2] + hi2[q] * u[p + ln.pe2]);
      // Non-cyclic ends: the ghost's part that does not follow the end cell, c0 = ghost - c1 u.
      if (!ln.cyclic && m == 0) rhs -= alo[q] * (u[p - ln.pd] - c1lo[line[g]] * u[p]);
      if (!ln.cyclic && m == n - 1) rhs -= ahi[q] * (u[p + ln.pd] - c1hi[line[g]] * u[p]);
      prev[g] = rhs - w[q] * prev[g];
      r[m * G + g] = prev[g];
    }
  double x[G] = {};
  for (int m = n - 1; m >= 0; --m)
    for (int g = 0; g < G; ++g) {
      const std::size_t q = q0[g] + static_cast<std::size_t>(m) * ln.qd;
      x[g] = (r[m * G + g] - (m == n - 1 ? 0.0 : ahi[q] * x[g])) * inv[q];
      r[m * G + g] = x[g];
    }
  for (int g = 0; g < G; ++g) {
    if (ln.cyclic) {
      const double* z = L.line_z.data();
      const double fact = (r[g] + L.line_cyclic[2 * line[g]] * r[(n - 1) * G + g]) / L.line_cyclic[2 * line[g] + 1];
      for (int m = 0; m < n; ++m) r[m * G + g] -= fact * z[q0[g] + static_cast<std::size_t>(m) * ln.qd];
    }
    for (int m = 0; m < n; ++m) u[p0[g] + m * ln.pd] = r[m * G + g];
  }
}

// One colour of a linear equation's lines, in groups of four along each row.
long long factored_pass(Level& L, const Lines3& ln, int colour, std::size_t first, std::size_t last) {
  constexpr int G = 4;
  const GridShape& s = L.shape;
  const Ops o(L);
  L.line_scratch.resize(static_cast<std::size_t>(G) * static_cast<std::size_t>(ln.n));
  double* r = L.line_scratch.data();
  std::size_t line[G], q0[G];
  std::ptrdiff_t p0[G];
  long long cells = 0;
  for (int t2 = 0; t2 < s.n[ln.e2]; ++t2) {
    int k = 0;
    for (int t1 = (colour + t2) & 1; t1 < s.n[ln.e1]; t1 += 2) {
      const std::size_t l = ln.line(L, t1, t2);
      if (l < first || l >= last) continue;
      line[k] = l;
      std::tie(q0[k], p0[k]) = ln.start(L, t1, t2);
      if (++k == G) factored_group<G>(L, ln, o, line, q0, p0, r), k = 0;
      cells += ln.n;
    }
    for (int g = 0; g < k; ++g) factored_group<1>(L, ln, o, line + g, q0 + g, p0 + g, r);
  }
  return cells;
}
}  // namespace

void factor_lines_3d(Level& L, const ScalarEquation& eq) {
  const GridShape& s = L.shape;
  L.factored = false;
  if (s.dimension != 3 || !L.s1.empty() || !L.s7.empty()) return;
  const std::size_t nc = L.cells();
  for (int d = 0; d < 3; ++d) {
    const Lines3 ln(L, d);
    L.line_w[d].resize(nc), L.line_inv[d].resize(nc);
    for (auto& c : L.end_c1[d]) c.assign(nc / static_cast<std::size_t>(ln.n), 0.0);
    if (ln.cyclic) L.line_z.resize(nc), L.line_cyclic.resize(2 * nc / static_cast<std::size_t>(ln.n));
    for (int t2 = 0; t2 < s.n[ln.e2]; ++t2)
      for (int t1 = 0; t1 < s.n[ln.e1]; ++t1)
        factor_line(L, ln, ln.start(L, t1, t2).first, ln.line(L, t1, t2), eq);
  }
  L.factored = true;
}

long long line_pass_3d(Level& L, const ScalarEquation& eq, int d, int colour, std::size_t first, std::size_t last) {
  const Lines3 ln(L, d);
  if (L.factored) return factored_pass(L, ln, colour, first, last);
  const GridShape& s = L.shape;
  const int n = ln.n;
  const Ops o(L);
  double* u = L.u.data();
  const bool nonlinear = o.nonlinear();
  const double *alo = o.lo[d], *ahi = o.hi[d], *lo1 = o.lo[ln.e1], *hi1 = o.hi[ln.e1], *lo2 = o.lo[ln.e2],
               *hi2 = o.hi[ln.e2];
  const auto nn = static_cast<std::size_t>(n);
  L.line_scratch.resize(5 * nn);
  double *a = L.line_scratch.data(), *b = a + nn, *c = b + nn, *r = c + nn, *z = r + nn;
  long long cells = 0;
  for (int t2 = 0; t2 < s.n[ln.e2]; ++t2)
    for (int t1 = 0; t1 < s.n[ln.e1]; ++t1) {
      const std::size_t line = ln.line(L, t1, t2);
      if (((t1 + t2) & 1) != colour || line < first || line >= last) continue;
      const auto [q0, p0] = ln.start(L, t1, t2);
      for (int m = 0; m < n; ++m) {
        const std::size_t q = q0 + static_cast<std::size_t>(m) * ln.qd;
        const std::ptrdiff_t p = p0 + m * ln.pd;
        const double u0 = u[p];
        double dR;
        double rhs = o.f[q] - (lo1[q] * u[p - ln.pe1] + hi1[q] * u[p + ln.pe1] + lo2[q] * u[p - ln.pe2] + hi2[q] * u[p + ln.pe2]);
        rhs += o.source_and_derivative(q, u0, dR) - dR * u0;  // one Newton linearisation per line
        double di = -o.diag[q] - dR;
        a[m] = alo[q], c[m] = ahi[q];
        if (!ln.cyclic && m == 0) {
          const double c1 = line_end_factor(L, eq, d, 0, line);
          rhs -= a[m] * (u[p - ln.pd] - c1 * u0), di += a[m] * c1, a[m] = 0.0;
        }
        if (!ln.cyclic && m == n - 1) {
          const double c1 = line_end_factor(L, eq, d, 1, line);
          rhs -= c[m] * (u[p + ln.pd] - c1 * u0), di += c[m] * c1, c[m] = 0.0;
        }
        b[m] = di, r[m] = rhs;
      }
      if (ln.cyclic) {
        cyclic_thomas(n, a, b, c, r, z);
      } else {
        thomas_factor(n, a, b, c);
        thomas_solve(n, a, b, c, r);
      }
      for (int m = 0; m < n; ++m) {
        double& um = u[p0 + m * ln.pd];
        double un = r[m];
        if (nonlinear && !(un > 0.1 * um)) un = 0.5 * um;  // keep psi positive
        um = un;
      }
      cells += n;
    }
  return cells;
}

namespace {
// Calls f(ghosted offset) for every cell of the lines of one colour in [first, last), in order.
template <class F>
void for_line_cells(const Level& L, int d, int colour, std::size_t first, std::size_t last, F&& f) {
  const Lines3 ln(L, d);
  const GridShape& s = L.shape;
  for (int t2 = 0; t2 < s.n[ln.e2]; ++t2)
    for (int t1 = 0; t1 < s.n[ln.e1]; ++t1) {
      const std::size_t line = ln.line(L, t1, t2);
      if (((t1 + t2) & 1) != colour || line < first || line >= last) continue;
      const std::ptrdiff_t p0 = ln.start(L, t1, t2).second;
      for (int m = 0; m < ln.n; ++m) f(static_cast<std::size_t>(p0 + m * ln.pd));
    }
}
}  // namespace

std::size_t line_cells_3d(const Level& L, int d, int colour, std::size_t first, std::size_t last) {
  std::size_t n = 0;
  for_line_cells(L, d, colour, first, last, [&](std::size_t) { ++n; });
  return n;
}

void pack_lines_3d(const Level& L, int d, int colour, std::size_t first, std::size_t last, std::vector<double>& out) {
  for_line_cells(L, d, colour, first, last, [&](std::size_t p) { out.push_back(L.u[p]); });
}

std::size_t unpack_lines_3d(Level& L, int d, int colour, std::size_t first, std::size_t last, const std::vector<double>& in,
                            std::size_t at) {
  for_line_cells(L, d, colour, first, last, [&](std::size_t p) { L.u[p] = in[at++]; });
  return at;
}

}  // namespace remnant::xcfc
