#include "shell_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "level_ops.hpp"
#include "line_relaxation_3d.hpp"

namespace remnant::xcfc {

int angular_shells(const Level& L) {
  const GridShape& s = L.shape;
  int i = 0;
  for (; i < s.n[0]; ++i) {
    const std::size_t q = L.cell(i, s.n[1] / 2, 0);
    if (L.a_lo[1][q] + L.a_hi[1][q] < L.a_lo[0][q] + L.a_hi[0][q]) break;
  }
  return i;
}

long long relax_inner_shells(Level& L, const ScalarEquation& eq, int shells) {
  const GridShape& s = L.shape;
  const int n0 = s.n[0], nt = s.n[1], np = s.n[2];
  const auto NT = static_cast<std::size_t>(nt), NP = static_cast<std::size_t>(np);
  if (L.dft_cos.size() != NP * NP) {
    L.dft_cos.resize(NP * NP), L.dft_sin.resize(NP * NP);
    for (std::size_t m = 0; m < NP; ++m)
      for (std::size_t k = 0; k < NP; ++k) {
        const double x = 2 * std::numbers::pi * static_cast<double>((m * k) % NP) / np;
        L.dft_cos[m * NP + k] = std::cos(x), L.dft_sin[m * NP + k] = std::sin(x);
      }
  }
  const int modes = np / 2 + 1;
  L.shell_scratch.resize(NT * NP + NT * 6 + NT * static_cast<std::size_t>(modes) * 2);
  double* res = L.shell_scratch.data();  // the shell's residual, [j][k]
  double* dRbar = res + NT * NP;
  double *a = dRbar + NT, *b = a + NT, *c = b + NT, *re = c + NT, *im = re + NT;
  double* hat = im + NT;  // per mode: the correction's real, then imaginary parts along theta
  const Ops o(L);
  const bool nonlinear = o.nonlinear();
  double* u = L.u.data();
  long long cells = 0;
  for (int i = 0; i < std::min(shells, n0); ++i) {
    // Residual f - A(u) and the phi-averaged source derivative per theta row.
    for (int j = 0; j < nt; ++j) {
      double acc = 0;
      for (int k = 0; k < np; ++k) {
        const std::size_t q = L.cell(i, j, k);
        const std::ptrdiff_t p = L.at(i, j, k);
        const double uc = u[p];
        double dR;
        const double src = o.source_and_derivative(q, uc, dR);
        res[static_cast<std::size_t>(j) * NP + static_cast<std::size_t>(k)] = o.f[q] - (o.sigma<3>(u, p, q) - o.diag[q] * uc - src);
        acc += dR;
      }
      dRbar[j] = acc / np;
    }
    // Per azimuthal mode m: the DFT of each row, one real tridiagonal matrix for both parts.
    double* out = hat;
    for (int m = 0; m < modes; ++m, out += 2 * NT) {
      for (int j = 0; j < nt; ++j) {
        const double* row = res + static_cast<std::size_t>(j) * NP;
        const double* cs = L.dft_cos.data() + static_cast<std::size_t>(m) * NP;
        const double* sn = L.dft_sin.data() + static_cast<std::size_t>(m) * NP;
        double sr = 0, si = 0;
        for (int k = 0; k < np; ++k) sr += row[k] * cs[k], si -= row[k] * sn[k];
        re[j] = sr, im[j] = si;
        const std::size_t q = L.cell(i, j, 0);
        const double aphi = o.lo[2][q];
        a[j] = o.lo[1][q], c[j] = o.hi[1][q];
        // The phi neighbours of mode m: 2 a_phi cos(2 pi m / n_phi) (a_phi the same on both faces).
        b[j] = 2 * aphi * L.dft_cos[static_cast<std::size_t>(m) * NP + 1] - o.diag[q] - dRbar[j];
      }
      // Theta ends (faces indexed k + n_phi i: the row's k = 0 entry, every k alike).
      const double c1lo = line_end_factor(L, eq, 1, 0, NP * static_cast<std::size_t>(i));
      const double c1hi = line_end_factor(L, eq, 1, 1, NP * static_cast<std::size_t>(i));
      b[0] += a[0] * c1lo, a[0] = 0;
      b[nt - 1] += c[nt - 1] * c1hi, c[nt - 1] = 0;
      thomas_factor(nt, a, b, c);
      thomas_solve(nt, a, b, c, re);
      thomas_solve(nt, a, b, c, im);
      for (int j = 0; j < nt; ++j) out[j] = re[j], out[NT + static_cast<std::size_t>(j)] = im[j];
    }
    // Inverse DFT and the update.
    for (int j = 0; j < nt; ++j)
      for (int k = 0; k < np; ++k) {
        double v = 0;
        const double* h = hat;
        for (int m = 0; m < modes; ++m, h += 2 * NT) {
          const double w = (m == 0 || 2 * m == np) ? 1.0 : 2.0;
          const std::size_t t = static_cast<std::size_t>(m) * NP + static_cast<std::size_t>(k);
          v += w * (h[j] * L.dft_cos[t] - h[NT + static_cast<std::size_t>(j)] * L.dft_sin[t]);
        }
        double& uc = u[L.at(i, j, k)];
        double un = uc + v / np;
        if (nonlinear && !(un > 0.1 * uc)) un = 0.5 * uc;
        uc = un;
      }
    cells += static_cast<long long>(nt) * np;
  }
  return cells;
}

}  // namespace remnant::xcfc
