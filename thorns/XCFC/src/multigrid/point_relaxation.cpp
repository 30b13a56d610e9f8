#include "point_relaxation.hpp"

namespace remnant::xcfc {
namespace {

template <int D>
long long red_black(Level& L, const Range& R, int colour) {
  const Ops o(L);
  const int n0 = L.shape.n[0];
  double* u = L.u.data();
  const bool nonlinear = o.nonlinear();
  long long n = 0;
  for (int k = R.k0; k < R.k1; ++k)
    for (int j = R.j0; j < R.j1; ++j) {
      const int i0 = (j + k + colour) & 1;
      n += (n0 - i0 + 1) / 2;
      std::size_t q = L.cell(i0, j, k);
      std::ptrdiff_t p = L.at(i0, j, k);
      for (int i = i0; i < n0; i += 2, q += 2, p += 2) {
        const double uc = u[p];
        const double res = o.sigma<D>(u, p, q) - o.diag[q] * uc - o.source(q, uc) - o.f[q];
        const double jac = -o.diag[q] - o.source_derivative(q, uc);
        double un = uc - res / jac;
        if (nonlinear && !(un > 0.1 * uc)) un = 0.5 * uc;  // keep psi-like unknowns positive
        u[p] = un;
      }
    }
  return n;
}

}  // namespace

void apply_operator(const Level& L, const std::vector<double>& u, std::vector<double>& out, const Range& R) {
  const Ops o(L);
  const double* uu = u.data();
  double* r = out.data();
  dispatch(L.shape.dimension, [&](auto D) {
    for_cells(L, R, [&](std::size_t q, std::ptrdiff_t p) {
      const double uc = uu[p];
      r[q] = o.template sigma<D()>(uu, p, q) - o.diag[q] * uc - o.source(q, uc);
    });
  });
}

long long red_black_pass(Level& L, const Range& R, int colour) {
  long long n = 0;
  dispatch(L.shape.dimension, [&](auto D) { n = red_black<D()>(L, R, colour); });
  return n;
}

}  // namespace remnant::xcfc
