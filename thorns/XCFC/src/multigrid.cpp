// FAS multigrid (see include/XCFC/multigrid.hpp): levels, boundary ghosts, red-black Newton-Gauss-
// Seidel, transfer operators, V-cycles and full multigrid.
#include "XCFC/multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "level.hpp"

namespace remnant::xcfc {

struct Multigrid::Impl {
  std::vector<Level> levels;

  explicit Impl(const GridShape& shape) {
    levels.emplace_back(shape);
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
    for (int d = 0; d < 3; ++d) {
      if (!s.used(d)) continue;
      const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
      for (int side = 0; side < 2; ++side) {
        const Boundary bc = s.boundary[d][side];
        const int ig = side == 0 ? -1 : s.n[d], iin = side == 0 ? 0 : s.n[d] - 1;
        for (int t2 = 0; t2 < s.n[e2]; ++t2)
          for (int t1 = 0; t1 < s.n[e1]; ++t1) {
            std::array<int, 3> g{}, m{};
            g[d] = ig, g[e1] = t1, g[e2] = t2;
            m = g;
            m[d] = iin;
            double& ghost = a[static_cast<std::size_t>(L.at(g[0], g[1], g[2]))];
            if (bc == Boundary::outer) {
              const double inner = a[static_cast<std::size_t>(L.at(m[0], m[1], m[2]))];
              if (eq.dirichlet) {
                Point3 xf = s.point(g[0], g[1], g[2]);
                xf[d] = s.face(d, side == 0 ? 0 : s.n[d]);
                ghost = (homogeneous ? 0.0 : 2.0 * eq.dirichlet(xf)) - inner;
              } else {
                const double u_inf = homogeneous ? 0.0 : eq.far_value;
                const std::size_t t = static_cast<std::size_t>(t1) + static_cast<std::size_t>(s.n[e1]) * t2;
                const double ratio = eq.falloff == 1.0   ? L.robin1[d][side][t]
                                     : eq.falloff == 2.0 ? L.robin2[d][side][t]
                                                         : std::pow(L.robin1[d][side][t], eq.falloff);
                ghost = u_inf + (inner - u_inf) * ratio;
              }
              continue;
            }
            if (bc == Boundary::origin && s.used(1) && s.origin_flips_theta()) m[1] = s.n[1] - 1 - m[1];
            ghost = eq.parity[d][side] * a[static_cast<std::size_t>(L.at(m[0], m[1], m[2]))];
          }
      }
    }
  }

  // ---- pointwise operator ------------------------------------------------------------------------
  struct Cell {
    double sigma, diag;
  };
  static Cell neighbours(const Level& L, const double* u, std::ptrdiff_t p, std::size_t q) {
    double sigma = 0;
    for (int d = 0; d < 3; ++d) {
      if (L.a_lo[d].empty()) continue;
      sigma += L.a_lo[d][q] * u[p - L.st[d]] + L.a_hi[d][q] * u[p + L.st[d]];
    }
    return {sigma, L.diagonal[q]};
  }
  static double source(const Level& L, std::size_t q, double u) {
    double r = L.k[q] * u + L.s0[q];
    if (!L.s1.empty()) r += L.s1[q] / u;
    if (!L.s7.empty()) {
      const double i2 = 1.0 / (u * u), i3 = i2 / u;
      r += L.s7[q] * i3 * i3 / u;
    }
    return r;
  }
  static double source_derivative(const Level& L, std::size_t q, double u) {
    double r = L.k[q];
    if (!L.s1.empty()) r -= L.s1[q] / (u * u);
    if (!L.s7.empty()) {
      const double i2 = 1.0 / (u * u), i4 = i2 * i2;
      r -= 7.0 * L.s7[q] * i4 * i4;
    }
    return r;
  }

  static void apply(const Level& L, const std::vector<double>& u, std::vector<double>& out) {
    const GridShape& s = L.shape;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i) {
          const std::size_t q = L.cell(i, j, k);
          const std::ptrdiff_t p = L.at(i, j, k);
          const Cell c = neighbours(L, u.data(), p, q);
          const double uc = u[static_cast<std::size_t>(p)];
          out[q] = c.sigma - c.diag * uc - source(L, q, uc);
        }
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
    const GridShape& s = L.shape;
    double m = 0;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i) {
          const std::size_t q = L.cell(i, j, k);
          const double u = L.u[static_cast<std::size_t>(L.at(i, j, k))];
          double t = std::abs(L.k[q] * u) + std::abs(L.s0[q]);
          if (!L.s1.empty()) t += std::abs(L.s1[q] / u);
          if (!L.s7.empty()) {
            const double u2 = u * u, u3 = u2 * u;
            t += std::abs(L.s7[q] / (u3 * u3 * u));
          }
          m = std::max(m, t);
        }
    return m;
  }

  // Red-black Gauss-Seidel, one Newton step per cell.
  static void smooth(Level& L, const ScalarEquation& eq, int sweeps) {
    const GridShape& s = L.shape;
    double* u = L.u.data();
    const bool nonlinear = !L.s1.empty() || !L.s7.empty();
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (int colour = 0; colour < 2; ++colour) {
        fill_ghosts(L, eq, L.u, false);
        for (int k = 0; k < s.n[2]; ++k)
          for (int j = 0; j < s.n[1]; ++j)
            for (int i = (j + k + colour) & 1; i < s.n[0]; i += 2) {
              const std::size_t q = L.cell(i, j, k);
              const std::ptrdiff_t p = L.at(i, j, k);
              const Cell c = neighbours(L, u, p, q);
              const double uc = u[p];
              const double res = c.sigma - c.diag * uc - source(L, q, uc) - L.f[q];
              const double jac = -c.diag - source_derivative(L, q, uc);
              double un = uc - res / jac;
              if (nonlinear && !(un > 0.1 * uc)) un = 0.5 * uc;  // keep psi-like unknowns positive
              u[p] = un;
            }
      }
  }

  // Zebra line Gauss-Seidel along direction d (one Newton linearisation per line, Thomas
  // algorithm): robust against the anisotropy of spherical grids (theta coupling dominates near the
  // origin, radial coupling far out). Line ends take the boundary ghost as an affine function of the
  // end cell (Robin, Dirichlet, parity); other ghosts are held.
  static void smooth_lines(Level& L, const ScalarEquation& eq, int d) {
    const GridShape& s = L.shape;
    const int n = s.n[d], e1 = (d + 1) % 3, e2 = (d + 2) % 3;
    double* u = L.u.data();
    const bool nonlinear = !L.s1.empty() || !L.s7.empty();
    double *lo = L.line_lo.data(), *di = L.line_di.data(), *up = L.line_up.data(), *rhs = L.line_rhs.data();
    for (int colour = 0; colour < 2; ++colour) {
      fill_ghosts(L, eq, L.u, false);
      for (int t2 = 0; t2 < s.n[e2]; ++t2)
        for (int t1 = 0; t1 < s.n[e1]; ++t1) {
          if (((t1 + t2) & 1) != colour) continue;
          std::array<int, 3> c{};
          c[e1] = t1, c[e2] = t2;
          for (int m = 0; m < n; ++m) {
            c[d] = m;
            const std::size_t q = L.cell(c[0], c[1], c[2]);
            const std::ptrdiff_t p = L.at(c[0], c[1], c[2]);
            double sigma = 0;
            for (int e = 0; e < 3; ++e) {
              if (e == d || L.a_lo[e].empty()) continue;
              sigma += L.a_lo[e][q] * u[p - L.st[e]] + L.a_hi[e][q] * u[p + L.st[e]];
            }
            const double u0 = u[p], dR = source_derivative(L, q, u0);
            lo[m] = L.a_lo[d][q];
            up[m] = L.a_hi[d][q];
            di[m] = -L.diagonal[q] - dR;
            rhs[m] = L.f[q] + source(L, q, u0) - dR * u0 - sigma;
          }
          // Line ends: ghost = c0 + c1 * u_end.
          for (int side = 0; side < 2; ++side) {
            const int end = side == 0 ? 0 : n - 1;
            c[d] = end;
            const std::ptrdiff_t p = L.at(c[0], c[1], c[2]);
            const std::ptrdiff_t pg = p + (side == 0 ? -L.st[d] : L.st[d]);
            const double ghost = u[pg], inner = u[p];
            double c1 = 0, c0 = ghost;
            const Boundary bc = s.boundary[d][side];
            if (bc == Boundary::outer) {
              if (eq.dirichlet) c1 = -1, c0 = ghost + inner;
              else {
                const double rho = (ghost - eq.far_value) / (inner - eq.far_value);
                if (std::isfinite(rho)) c1 = rho, c0 = eq.far_value * (1 - rho);
              }
            } else if (!(bc == Boundary::origin && s.used(1) && s.origin_flips_theta())) {
              c1 = eq.parity[d][side], c0 = 0;
            }
            double& a = side == 0 ? lo[end] : up[end];
            di[end] += a * c1;
            rhs[end] -= a * c0;
            a = 0;
          }
          // Thomas algorithm.
          for (int m = 1; m < n; ++m) {
            const double w = lo[m] / di[m - 1];
            di[m] -= w * up[m - 1];
            rhs[m] -= w * rhs[m - 1];
          }
          rhs[n - 1] /= di[n - 1];
          for (int m = n - 2; m >= 0; --m) rhs[m] = (rhs[m] - up[m] * rhs[m + 1]) / di[m];
          for (int m = 0; m < n; ++m) {
            c[d] = m;
            const std::ptrdiff_t p = L.at(c[0], c[1], c[2]);
            double un = rhs[m];
            if (nonlinear && !(un > 0.1 * u[p])) un = 0.5 * u[p];
            u[p] = un;
          }
        }
    }
  }

  // Local relaxation next to the spherical origin (Brandt): the large coefficients there leave the
  // largest residual after a red-black sweep, which otherwise dominates the L-infinity stopping
  // test for V-cycles after the rest of the grid has converged.
  static void relax_origin(Level& L, const ScalarEquation& eq) {
    const GridShape& s = L.shape;
    if (s.dimension != 1 || s.boundary[0][0] != Boundary::origin) return;
    double* u = L.u.data();
    const bool nonlinear = !L.s1.empty() || !L.s7.empty();
    const int m = std::min(s.n[0], 4);
    for (int pass = 0; pass < 2; ++pass) {
      u[L.at(-1, 0, 0)] = eq.parity[0][0] * u[L.at(0, 0, 0)];
      for (int i = 0; i < m; ++i) {
        const std::size_t q = static_cast<std::size_t>(i);
        const std::ptrdiff_t p = L.at(i, 0, 0);
        const Cell c = neighbours(L, u, p, q);
        const double uc = u[p];
        const double res = c.sigma - c.diag * uc - source(L, q, uc) - L.f[q];
        double un = uc - res / (-c.diag - source_derivative(L, q, uc));
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
  void coarse_solve(Level& L, const ScalarEquation& eq, int max_sweeps) {
    const double r0 = residual(L, eq);
    for (int done = 0; done < max_sweeps; done += 10) {
      relax(L, eq, 10);
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

  // Equation coefficients on every level.
  void set_equation(const ScalarEquation& eq) {
    const std::size_t n = levels[0].cells();
    auto fine = [&](const std::vector<double>& v, std::vector<double>& out) {
      if (v.empty()) out.assign(n, 0.0);
      else out = v;
    };
    Level& L0 = levels[0];
    fine(eq.k, L0.k);
    fine(eq.s0, L0.s0);
    if (eq.s1.empty()) L0.s1.clear(); else L0.s1 = eq.s1;
    if (eq.s7.empty()) L0.s7.clear(); else L0.s7 = eq.s7;
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
      Level &F = levels[l], &C = levels[l + 1];
      restrict_interior(F, C, F.k, C.k);
      restrict_interior(F, C, F.s0, C.s0);
      if (F.s1.empty()) C.s1.clear(); else restrict_interior(F, C, F.s1, C.s1);
      if (F.s7.empty()) C.s7.clear(); else restrict_interior(F, C, F.s7, C.s7);
    }
    // The geometric point term is rediscretised on each level, not restricted.
    for (auto& L : levels) {
      const auto& mk = L.mode_k[static_cast<int>(eq.mode)];
      if (eq.mode != AngularMode::none)
        for (std::size_t q = 0; q < L.k.size(); ++q) L.k[q] += mk[q];
      L.f.assign(L.cells(), 0.0);
      L.r.assign(L.cells(), 0.0);
      L.u.assign(L.ghosted_size, 0.0);
    }
  }
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
  m.set_equation(eq);
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
  if (s.full_multigrid) m.full_multigrid(eq, s);
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
  while (res > std::max(s.tolerance * st.scale, noise) && st.cycles < s.max_cycles) {
    m.vcycle(0, eq, s);
    ++st.cycles;
    res = Impl::residual(L, eq);
    st.scale = scale();
    st.history.push_back(res);
    if (std::getenv("XCFC_DEBUG")) {
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
  m.set_equation(eq);
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

}  // namespace remnant::xcfc
