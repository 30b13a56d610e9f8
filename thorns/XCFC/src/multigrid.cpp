// FAS multigrid (see include/XCFC/multigrid.hpp): levels, boundary ghosts, red-black Newton-Gauss-
// Seidel, transfer operators, V-cycles and full multigrid.
#include "XCFC/multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>

#include "level.hpp"

namespace remnant::xcfc {

struct Multigrid::Impl {
  std::vector<Level> levels;
  CellFrames frames;

  explicit Impl(const GridShape& shape) {
    levels.emplace_back(shape);
    {
      const Level& L = levels[0];
      frames.J.assign(L.ghosted_size, Matrix3{});
      frames.f.assign(L.ghosted_size, Point3{1, 1, 1});
      for (int k = -L.g[2]; k < shape.n[2] + L.g[2]; ++k)
        for (int j = -L.g[1]; j < shape.n[1] + L.g[1]; ++j)
          for (int i = -L.g[0]; i < shape.n[0] + L.g[0]; ++i) {
            const Point3 x = shape.point(i, j, k);
            const auto p = static_cast<std::size_t>(L.at(i, j, k));
            frames.J[p] = coords::jacobian(shape.coordinates, x);
            frames.f[p] = coords::metric_diagonal(shape.coordinates, x);
          }
    }
    for (;;) {
      const GridShape& s = levels.back().shape;
      GridShape c = s;
      bool coarsened = false;
      std::array<int, 3> ratio{1, 1, 1};
      for (int d = 0; d < 3; ++d)
        if (s.used(d) && s.n[d] % 2 == 0 && s.n[d] >= 4) {
          ratio[d] = 2;
          c.n[d] = s.n[d] / 2;
          c.dx[d] = 2 * s.dx[d];
          coarsened = true;
        }
      if (!coarsened) break;
      levels.back().ratio = ratio;
      levels.emplace_back(c);
    }
    // Restriction weights: the fine volumes summed per coarse cell (in the order of restriction).
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
      const Level& F = levels[l];
      Level& C = levels[l + 1];
      C.restrict_volume.assign(C.cells(), 0.0);
      const GridShape& fs = F.shape;
      for (int k = 0; k < fs.n[2]; ++k)
        for (int j = 0; j < fs.n[1]; ++j)
          for (int i = 0; i < fs.n[0]; ++i)
            C.restrict_volume[C.cell(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2])] += F.volume[F.cell(i, j, k)];
    }
  }

  // ---- boundary ghosts -------------------------------------------------------------------------
  // Fills the face ghosts of a ghosted array (no corners: no stencil uses them). `homogeneous`:
  // the conditions of a correction (far value 0, Dirichlet value 0).
  static void fill_ghosts(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous) {
    const GridShape& s = L.shape;
    double* v = a.data();
    for (int d = 0; d < 3; ++d) {
      if (!s.used(d)) continue;
      for (int side = 0; side < 2; ++side) {
        const Level::GhostFace& gf = L.ghost_faces[d][side];
        const std::ptrdiff_t *g = gf.ghost.data(), *in = gf.inner.data(), *mi = gf.mirror.data();
        const std::size_t count = gf.ghost.size();
        if (s.boundary[d][side] != Boundary::outer) {
          const double parity = eq.parity[d][side];
          for (std::size_t t = 0; t < count; ++t) v[g[t]] = parity * v[mi[t]];
        } else if (eq.dirichlet) {
          fill_dirichlet(L, eq, a, homogeneous, d, side);
        } else {
          const double u_inf = homogeneous ? 0.0 : eq.far_value;
          const std::vector<double>& r = eq.falloff == 2.0 ? L.robin2[d][side] : L.robin1[d][side];
          const bool power = eq.falloff != 1.0 && eq.falloff != 2.0;
          for (std::size_t t = 0; t < count; ++t) {
            const double ratio = power ? std::pow(r[t], eq.falloff) : r[t];
            v[g[t]] = u_inf + (v[in[t]] - u_inf) * ratio;
          }
        }
      }
    }
  }
  // Dirichlet values at the outer faces (manufactured solutions only: a callback per ghost).
  static void fill_dirichlet(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous, int d,
                             int side) {
    const GridShape& s = L.shape;
    const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
    const Level::GhostFace& gf = L.ghost_faces[d][side];
    std::size_t t = 0;
    for (int t2 = 0; t2 < s.n[e2]; ++t2)
      for (int t1 = 0; t1 < s.n[e1]; ++t1, ++t) {
        std::array<int, 3> g{};
        g[d] = side == 0 ? -1 : s.n[d], g[e1] = t1, g[e2] = t2;
        Point3 xf = s.point(g[0], g[1], g[2]);
        xf[d] = s.face(d, side == 0 ? 0 : s.n[d]);
        const double inner = a[static_cast<std::size_t>(gf.inner[t])];
        a[static_cast<std::size_t>(gf.ghost[t])] = (homogeneous ? 0.0 : 2.0 * eq.dirichlet(xf)) - inner;
      }
  }

  // ---- pointwise operator ------------------------------------------------------------------------
  // Raw pointers of one level's operator and equation, hoisted out of the cell loops (s1, s7 null
  // when absent).
  struct Ops {
    const double* lo[3]{};
    const double* hi[3]{};
    const double *diag, *k, *s0, *s1, *s7, *f;
    std::ptrdiff_t st[3];
    explicit Ops(const Level& L)
        : diag(L.diagonal.data()), k(L.k.data()), s0(L.s0.data()), s1(L.s1.empty() ? nullptr : L.s1.data()),
          s7(L.s7.empty() ? nullptr : L.s7.data()), f(L.f.data()), st{L.st[0], L.st[1], L.st[2]} {
      for (int d = 0; d < 3; ++d)
        if (!L.a_lo[d].empty()) lo[d] = L.a_lo[d].data(), hi[d] = L.a_hi[d].data();
    }
    bool nonlinear() const { return s1 || s7; }
    double source(std::size_t q, double u) const {
      double r = k[q] * u + s0[q];
      if (s1) r += s1[q] / u;
      if (s7) {
        const double i2 = 1.0 / (u * u), i3 = i2 / u;
        r += s7[q] * i3 * i3 / u;
      }
      return r;
    }
    double source_derivative(std::size_t q, double u) const {
      double r = k[q];
      if (s1) r -= s1[q] / (u * u);
      if (s7) {
        const double i2 = 1.0 / (u * u), i4 = i2 * i2;
        r -= 7.0 * s7[q] * i4 * i4;
      }
      return r;
    }
    // Source and its derivative with one reciprocal (the nonlinear line relaxation).
    double source_and_derivative(std::size_t q, double u, double& dR) const {
      const double i1 = 1.0 / u;
      double r = k[q] * u + s0[q];
      dR = k[q];
      if (s1) r += s1[q] * i1, dR -= s1[q] * i1 * i1;
      if (s7) {
        const double i2 = i1 * i1, i4 = i2 * i2, i7 = i4 * i2 * i1;
        r += s7[q] * i7, dR -= 7.0 * s7[q] * i7 * i1;
      }
      return r;
    }
    template <int D>
    double sigma(const double* u, std::ptrdiff_t p, std::size_t q) const {
      double s = lo[0][q] * u[p - 1] + hi[0][q] * u[p + 1];
      if constexpr (D >= 2) s += lo[1][q] * u[p - st[1]] + hi[1][q] * u[p + st[1]];
      if constexpr (D >= 3) s += lo[2][q] * u[p - st[2]] + hi[2][q] * u[p + st[2]];
      return s;
    }
  };

  // Calls f(q, p) for every interior cell in storage order (q interior, p ghosted index).
  template <class F>
  static void for_cells(const Level& L, F&& f) {
    const GridShape& s = L.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j) {
        std::size_t q = L.cell(0, j, k);
        std::ptrdiff_t p = L.at(0, j, k);
        for (int i = 0; i < s.n[0]; ++i, ++q, ++p) f(q, p);
      }
  }
  template <class F>
  static void dispatch(int dimension, F&& f) {
    if (dimension == 1) f(std::integral_constant<int, 1>{});
    else if (dimension == 2) f(std::integral_constant<int, 2>{});
    else f(std::integral_constant<int, 3>{});
  }

  static void apply(const Level& L, const std::vector<double>& u, std::vector<double>& out) {
    const Ops o(L);
    const double* uu = u.data();
    double* r = out.data();
    dispatch(L.shape.dimension, [&](auto D) {
      for_cells(L, [&](std::size_t q, std::ptrdiff_t p) {
        const double uc = uu[p];
        r[q] = o.template sigma<D()>(uu, p, q) - o.diag[q] * uc - o.source(q, uc);
      });
    });
  }

  // r = f - A(u); returns max|r|.
  static double residual(Level& L, const ScalarEquation& eq) {
    fill_ghosts(L, eq, L.u, false);
    apply(L, L.u, L.r);
    double m = 0;
    for (std::size_t q = 0; q < L.r.size(); ++q) {
      L.r[q] = L.f[q] - L.r[q];
      m = std::max(m, std::abs(L.r[q]));
    }
    return m;
  }

  // Max of the source terms' magnitudes at u: the scale of the residual.
  static double source_scale(const Level& L) {
    const Ops o(L);
    double m = 0;
    for_cells(L, [&](std::size_t q, std::ptrdiff_t p) {
      const double u = L.u[static_cast<std::size_t>(p)];
      double t = std::abs(o.k[q] * u) + std::abs(o.s0[q]);
      if (o.s1) t += std::abs(o.s1[q] / u);
      if (o.s7) {
        const double u2 = u * u, u3 = u2 * u;
        t += std::abs(o.s7[q] / (u3 * u3 * u));
      }
      m = std::max(m, t);
    });
    return m;
  }

  // Red-black Gauss-Seidel, one Newton step per cell.
  template <int D>
  static void smooth_dim(Level& L, const ScalarEquation& eq, int sweeps) {
    const GridShape& s = L.shape;
    const Ops o(L);
    double* u = L.u.data();
    const bool nonlinear = o.nonlinear();
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int colour = 0; colour < 2; ++colour) {
        fill_ghosts(L, eq, L.u, false);
        for (int k = 0; k < s.n[2]; ++k)
          for (int j = 0; j < s.n[1]; ++j) {
            const int i0 = (j + k + colour) & 1;
            std::size_t q = L.cell(i0, j, k);
            std::ptrdiff_t p = L.at(i0, j, k);
            for (int i = i0; i < s.n[0]; i += 2, q += 2, p += 2) {
              const double uc = u[p];
              const double res = o.sigma<D>(u, p, q) - o.diag[q] * uc - o.source(q, uc) - o.f[q];
              const double jac = -o.diag[q] - o.source_derivative(q, uc);
              double un = uc - res / jac;
              if (nonlinear && !(un > 0.1 * uc)) un = 0.5 * uc;  // keep psi-like unknowns positive
              u[p] = un;
            }
          }
      }
  }
  static void smooth(Level& L, const ScalarEquation& eq, int sweeps) {
    dispatch(L.shape.dimension, [&](auto D) { smooth_dim<D()>(L, eq, sweeps); });
  }

  // Line geometry of direction d on a 1D or 2D level: lines are indexed by t along the transverse
  // direction e (none in 1D); interior and ghosted strides along and across the lines.
  struct Lines {
    int d, e, n, count;
    std::ptrdiff_t qd, qe, pd, pe;
    Lines(const Level& L, int dir) : d(dir), e(L.shape.dimension == 2 ? 1 - dir : -1), n(L.shape.n[dir]) {
      const GridShape& s = L.shape;
      count = e < 0 ? 1 : s.n[e];
      qd = d == 0 ? 1 : s.n[0];
      qe = e == 0 ? 1 : s.n[0];
      pd = L.st[d];
      pe = e < 0 ? 0 : L.st[e];
    }
    std::size_t q0(int t) const { return static_cast<std::size_t>(t * qe); }
    std::ptrdiff_t p0(const Level& L, int t) const { return d == 0 ? L.at(0, e < 0 ? 0 : t, 0) : L.at(t, 0, 0); }
  };

  // Line ends: ghost = c0 + c1 * u_end, c1 from the boundary kind (the Robin ratio is geometry);
  // c0 is taken from the current ghost in the relaxation.
  static void set_line_ends(Level& L, const ScalarEquation& eq) {
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
            c1 = eq.dirichlet ? -1.0 : eq.falloff == 1.0 ? ratio
                                     : eq.falloff == 2.0 ? L.robin2[d][side][static_cast<std::size_t>(t)]
                                                         : std::pow(ratio, eq.falloff);
          } else if (bc == Boundary::origin && s.used(1) && s.origin_flips_theta()) {
            c1 = 0.0;  // the mirror cell lies on another line: its value is held
          }
          L.end_c1[d][side][static_cast<std::size_t>(t)] = c1;
        }
      }
    }
  }

  // Thomas forward-elimination factors of the (fixed) line matrices of a linear equation.
  static void factor_lines(Level& L) {
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

  // Zebra line Gauss-Seidel along direction d (Thomas algorithm): robust against the anisotropy of
  // spherical grids (theta coupling dominates near the origin, radial coupling far out). Linear
  // equations use the factors of factor_lines (substitutions only); nonlinear ones take one Newton
  // linearisation per line. Line ends take the boundary ghost as an affine function of the end
  // cell; other ghosts are held. In 1D the single line is an exact (Newton) solve.
  template <bool Factored>
  static void line_pass(Level& L, const Lines& ln, int colour) {
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
    for (int t = colour; t < ln.count; t += 2) {
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
  }
  static void smooth_lines(Level& L, const ScalarEquation& eq, int d) {
    const Lines ln(L, d);
    for (int colour = 0; colour < (ln.count > 1 ? 2 : 1); ++colour) {
      fill_ghosts(L, eq, L.u, false);
      if (L.factored) line_pass<true>(L, ln, colour);
      else line_pass<false>(L, ln, colour);
    }
  }

  // Local relaxation next to the spherical origin (Brandt): the large coefficients there leave the
  // largest residual after a red-black sweep, which otherwise dominates the L-infinity stopping
  // test for V-cycles after the rest of the grid has converged.
  static void relax_origin(Level& L, const ScalarEquation& eq) {
    const GridShape& s = L.shape;
    if (s.dimension != 1 || s.boundary[0][0] != Boundary::origin) return;
    double* u = L.u.data();
    const Ops o(L);
    const bool nonlinear = o.nonlinear();
    const int m = std::min(s.n[0], 4);
    for (int pass = 0; pass < 2; ++pass) {
      u[L.at(-1, 0, 0)] = eq.parity[0][0] * u[L.at(0, 0, 0)];
      for (int i = 0; i < m; ++i) {
        const std::size_t q = static_cast<std::size_t>(i);
        const std::ptrdiff_t p = L.at(i, 0, 0);
        const double uc = u[p];
        const double res = o.sigma<1>(u, p, q) - o.diag[q] * uc - o.source(q, uc) - o.f[q];
        double un = uc - res / (-o.diag[q] - o.source_derivative(q, uc));
        if (nonlinear && !(un > 0.1 * uc)) un = 0.5 * uc;
        u[p] = un;
        if (i == 0) u[L.at(-1, 0, 0)] = eq.parity[0][0] * un;
      }
    }
  }

  // Point red-black smoothing in 1D and isotropic 3D, alternating line smoothing in 2D.
  static void relax(Level& L, const ScalarEquation& eq, int sweeps) {
    if (L.shape.dimension != 2) {
      smooth(L, eq, sweeps);
      return relax_origin(L, eq);
    }
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int d = 0; d < 2; ++d) smooth_lines(L, eq, d);
  }

  // ---- transfers ---------------------------------------------------------------------------------
  // Volume-weighted restriction of an interior array (fine -> coarse).
  static void restrict_interior(const Level& F, const Level& C, const std::vector<double>& fine,
                                std::vector<double>& coarse) {
    coarse.assign(C.cells(), 0.0);
    const GridShape& s = F.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i) {
          const std::size_t q = F.cell(i, j, k);
          coarse[C.cell(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2])] += F.volume[q] * fine[q];
        }
    for (std::size_t q = 0; q < coarse.size(); ++q) coarse[q] /= C.restrict_volume[q];
  }
  // The same from and to ghosted arrays (coarse ghosts zeroed, to be filled by the caller).
  static void restrict_ghosted(const Level& F, const Level& C, const std::vector<double>& fine,
                               std::vector<double>& coarse) {
    coarse.assign(C.ghosted_size, 0.0);
    const GridShape& s = F.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i)
          coarse[static_cast<std::size_t>(C.at(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2]))] +=
              F.volume[F.cell(i, j, k)] * fine[static_cast<std::size_t>(F.at(i, j, k))];
    const GridShape& c = C.shape;
    for (int k = 0; k < c.n[2]; ++k)
      for (int j = 0; j < c.n[1]; ++j)
        for (int i = 0; i < c.n[0]; ++i) coarse[static_cast<std::size_t>(C.at(i, j, k))] /= C.restrict_volume[C.cell(i, j, k)];
  }
  // Adds (or, with `replace`, writes) the linear interpolation of a ghosted coarse array: each fine
  // cell takes the coarse value plus a quarter of the central coarse slope per refined direction.
  static void prolong(const Level& C, const Level& F, const std::vector<double>& coarse, std::vector<double>& fine,
                      bool replace) {
    const GridShape& s = F.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i) {
          const std::array<int, 3> f{i, j, k};
          std::array<int, 3> c{};
          for (int d = 0; d < 3; ++d) c[d] = f[d] / F.ratio[d];
          const std::ptrdiff_t pc = C.at(c[0], c[1], c[2]);
          double v = coarse[static_cast<std::size_t>(pc)];
          for (int d = 0; d < 3; ++d) {
            if (F.ratio[d] != 2) continue;
            const double sign = (f[d] & 1) ? 0.125 : -0.125;
            v += sign * (coarse[static_cast<std::size_t>(pc + C.st[d])] - coarse[static_cast<std::size_t>(pc - C.st[d])]);
          }
          double& out = fine[static_cast<std::size_t>(F.at(i, j, k))];
          out = replace ? v : out + v;
        }
  }

  // ---- cycles ------------------------------------------------------------------------------------
  // Coarsest level: relaxation to 1e-8 of the initial residual. A 1D level is one line, solved
  // exactly (linear) or by Newton line solves, so it needs no point sweeps at all.
  void coarse_solve(Level& L, const ScalarEquation& eq, int max_sweeps) {
    const double r0 = residual(L, eq);
    if (L.shape.dimension == 1) {
      for (int done = 0; done < max_sweeps; ++done) {
        smooth_lines(L, eq, 0);
        if (residual(L, eq) <= 1e-8 * r0) break;
      }
      return;
    }
    const int chunk = L.cells() <= 64 ? 2 : 10;  // tiny levels: check often, residuals are cheap
    for (int done = 0; done < max_sweeps; done += chunk) {
      relax(L, eq, chunk);
      if (residual(L, eq) <= 1e-8 * r0) break;
    }
  }

  void vcycle(std::size_t l, const ScalarEquation& eq, const SolveSettings& s) {
    Level& F = levels[l];
    if (l + 1 == levels.size()) {
      coarse_solve(F, eq, std::max(s.coarse_sweeps, 20 * static_cast<int>(F.cells())));
      return;
    }
    Level& C = levels[l + 1];
    relax(F, eq, s.pre_sweeps);
    residual(F, eq);
    restrict_ghosted(F, C, F.u, C.u);
    fill_ghosts(C, eq, C.u, false);
    C.ubar = C.u;
    restrict_interior(F, C, F.r, C.f);
    apply(C, C.ubar, C.r);  // C.r as scratch: the coarse cycle recomputes it before use
    for (std::size_t q = 0; q < C.r.size(); ++q) C.f[q] += C.r[q];
    vcycle(l + 1, eq, s);
    for (std::size_t p = 0; p < C.u.size(); ++p) C.ubar[p] = C.u[p] - C.ubar[p];
    fill_ghosts(C, eq, C.ubar, true);
    prolong(C, F, C.ubar, F.u, false);
    relax(F, eq, s.post_sweeps);
  }

  void full_multigrid(const ScalarEquation& eq, const SolveSettings& s) {
    set_coarse_equations(eq);
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) restrict_ghosted(levels[l], levels[l + 1], levels[l].u, levels[l + 1].u);
    for (auto& L : levels) std::fill(L.f.begin(), L.f.end(), 0.0);
    Level& coarsest = levels.back();
    coarse_solve(coarsest, eq, std::max(s.coarse_sweeps, 20 * static_cast<int>(coarsest.cells())));
    for (std::size_t l = levels.size() - 1; l-- > 0;) {
      fill_ghosts(levels[l + 1], eq, levels[l + 1].u, false);
      prolong(levels[l + 1], levels[l], levels[l + 1].u, levels[l].u, true);
      for (std::size_t m = l; m < levels.size(); ++m) std::fill(levels[m].f.begin(), levels[m].f.end(), 0.0);
      vcycle(l, eq, s);
    }
  }

  // Equation coefficients: set_fine_equation on the finest level (all a residual needs);
  // set_coarse_equations on the coarse levels, line ends and line factors everywhere, only once a
  // cycle is needed (a warm start that already meets the tolerance costs one residual).
  void set_fine_equation(const ScalarEquation& eq) {
    Level& L0 = levels[0];
    const std::size_t n = L0.cells();
    auto copy = [&](const std::vector<double>& v, std::vector<double>& out) {
      if (v.empty()) out.assign(n, 0.0);
      else out.assign(v.begin(), v.end());
    };
    copy(eq.k, L0.k_eq);
    copy(eq.s0, L0.s0);
    if (eq.s1.empty()) L0.s1.clear(); else L0.s1.assign(eq.s1.begin(), eq.s1.end());
    if (eq.s7.empty()) L0.s7.clear(); else L0.s7.assign(eq.s7.begin(), eq.s7.end());
    // The geometric point term is rediscretised on each level, not restricted.
    L0.k = L0.k_eq;
    if (eq.mode != AngularMode::none) {
      const auto& mk = L0.mode_k[static_cast<int>(eq.mode)];
      for (std::size_t q = 0; q < n; ++q) L0.k[q] += mk[q];
    }
    L0.f.assign(n, 0.0);
    L0.r.resize(n);
    if (L0.u.size() != L0.ghosted_size) L0.u.assign(L0.ghosted_size, 0.0);
    L0.factored = false;
    coarse_ready = false;
  }
  void set_coarse_equations(const ScalarEquation& eq) {
    if (coarse_ready) return;
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
      Level &F = levels[l], &C = levels[l + 1];
      restrict_interior(F, C, F.k_eq, C.k_eq);
      restrict_interior(F, C, F.s0, C.s0);
      if (F.s1.empty()) C.s1.clear(); else restrict_interior(F, C, F.s1, C.s1);
      if (F.s7.empty()) C.s7.clear(); else restrict_interior(F, C, F.s7, C.s7);
      C.k = C.k_eq;
      if (eq.mode != AngularMode::none) {
        const auto& mk = C.mode_k[static_cast<int>(eq.mode)];
        for (std::size_t q = 0; q < C.k.size(); ++q) C.k[q] += mk[q];
      }
      C.f.resize(C.cells());
      C.r.resize(C.cells());
      if (C.u.size() != C.ghosted_size) C.u.assign(C.ghosted_size, 0.0);
    }
    for (auto& L : levels) {
      set_line_ends(L, eq);
      factor_lines(L);
    }
    coarse_ready = true;
  }
  bool coarse_ready = false;

  void load(const std::vector<double>& u) {
    Level& L = levels[0];
    const GridShape& s = L.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i) L.u[static_cast<std::size_t>(L.at(i, j, k))] = u[L.cell(i, j, k)];
  }
  void store(std::vector<double>& u) const {
    const Level& L = levels[0];
    const GridShape& s = L.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i) u[L.cell(i, j, k)] = L.u[static_cast<std::size_t>(L.at(i, j, k))];
  }
};

Multigrid::Multigrid(const GridShape& shape) : impl_(std::make_unique<Impl>(shape)) {}
Multigrid::~Multigrid() = default;
Multigrid::Multigrid(Multigrid&&) noexcept = default;
Multigrid& Multigrid::operator=(Multigrid&&) noexcept = default;

const GridShape& Multigrid::shape() const { return impl_->levels[0].shape; }
int Multigrid::levels() const { return static_cast<int>(impl_->levels.size()); }

SolveStats Multigrid::solve(const ScalarEquation& eq, std::vector<double>& u, const SolveSettings& s) {
  Impl& m = *impl_;
  const std::size_t n = m.levels[0].cells();
  if (u.size() != n) u.assign(n, eq.nonlinear() ? 1.0 : 0.0);
  m.set_fine_equation(eq);
  m.load(u);
  SolveStats st;
  Level& L = m.levels[0];
  // No sources, no boundary values: the solution is zero (no cycles spent on round-off).
  const bool trivial = !eq.dirichlet && eq.far_value == 0.0 && !eq.nonlinear() &&
                       std::all_of(L.s0.begin(), L.s0.end(), [](double v) { return v == 0.0; });
  if (trivial) {
    std::fill(u.begin(), u.end(), 0.0);
    st.converged = true;
    return st;
  }
  // 1D: the whole level is one line, and a line solve is exact for linear equations (Newton for
  // psi), so each "cycle" is one tridiagonal solve on the finest level.
  const bool line_solve = s.direct_1d && L.shape.dimension == 1;
  if (s.full_multigrid && !line_solve) m.full_multigrid(eq, s);
  st.initial_residual = Impl::residual(L, eq);
  double res = st.initial_residual;
  auto scale = [&] {
    const double sc = std::max(Impl::source_scale(L), s.scale_floor);
    return sc > 0 ? sc : 1.0;
  };
  st.scale = scale();
  // Round-off floor of the residual: the largest operator term times a few ulps. Near the spherical
  // origin and axis the coefficients are large and a relative 1e-10 can lie below it.
  auto floor = [&] {
    const double m = L.max_diagonal;
    double umax = 0;
    for (double v : L.u) umax = std::max(umax, std::abs(v));
    return 256 * std::numeric_limits<double>::epsilon() * m * umax;
  };
  const double noise = floor();
  static const bool debug = std::getenv("XCFC_DEBUG") != nullptr;
  while (res > std::max(s.tolerance * st.scale, noise) && st.cycles < s.max_cycles) {
    m.set_coarse_equations(eq);
    if (line_solve) Impl::smooth_lines(L, eq, 0);
    else m.vcycle(0, eq, s);
    ++st.cycles;
    res = Impl::residual(L, eq);
    st.scale = scale();
    st.history.push_back(res);
    if (debug) {
      std::size_t at = 0;
      for (std::size_t q = 0; q < L.r.size(); ++q) if (std::abs(L.r[q]) > std::abs(L.r[at])) at = q;
      std::fprintf(stderr, "cycle %d residual %.3e at %zu (initial %.3e, target %.3e)\n", st.cycles, res, at, st.initial_residual, s.tolerance * st.scale);
    }
  }
  st.residual = res;
  st.converged = res <= std::max(s.tolerance * st.scale, noise);
  st.factor = st.cycles > 0 && st.initial_residual > 0 ? std::pow(res / st.initial_residual, 1.0 / st.cycles) : 0.0;
  m.store(u);
  return st;
}

double Multigrid::residual_norm(const ScalarEquation& eq, const std::vector<double>& u) {
  Impl& m = *impl_;
  m.set_fine_equation(eq);
  m.load(u);
  return Impl::residual(m.levels[0], eq);
}

std::vector<double> Multigrid::with_ghosts(const ScalarEquation& eq, const std::vector<double>& u) const {
  const Level& L = impl_->levels[0];
  std::vector<double> a(L.ghosted_size, 0.0);
  const GridShape& s = L.shape;
  for (int k = 0; k < s.n[2]; ++k)
    for (int j = 0; j < s.n[1]; ++j)
      for (int i = 0; i < s.n[0]; ++i) a[static_cast<std::size_t>(L.at(i, j, k))] = u[L.cell(i, j, k)];
  Impl::fill_ghosts(L, eq, a, false);
  return a;
}

std::ptrdiff_t Multigrid::ghosted_index(int i, int j, int k) const { return impl_->levels[0].at(i, j, k); }
std::array<std::ptrdiff_t, 3> Multigrid::ghosted_strides() const { return impl_->levels[0].st; }
const CellFrames& Multigrid::frames() const { return impl_->frames; }

}  // namespace remnant::xcfc
