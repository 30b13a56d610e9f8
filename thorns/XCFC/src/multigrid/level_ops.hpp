#pragma once
// Kernel helpers shared by the multigrid's smoothers, residuals and transfers: cell ranges of a
// level, the level's operator and equation as raw pointers (hoisted out of the cell loops), a cell
// loop in storage order, and the dimension dispatch of the templated stencils.
#include <cstddef>
#include <type_traits>

#include "level.hpp"

namespace remnant::xcfc {

// Interior cells of a level as index ranges (i always complete).
struct Range {
  int j0, j1, k0, k1;
};
inline Range full_range(const Level& L) { return {0, L.shape.n[1], 0, L.shape.n[2]}; }

// Raw pointers of one level's operator and equation, hoisted out of the cell loops (s1, s7 null
// when absent).
struct Ops {
  const double* lo[3]{};
  const double* hi[3]{};
  const double *diag, *k, *s0, *s1, *s7, *f;
  std::ptrdiff_t st[3];
  explicit Ops(const Level& L)
      : diag(L.diagonal.data()),
        k(L.k.data()),
        s0(L.s0.data()),
        s1(L.s1.empty() ? nullptr : L.s1.data()),
        s7(L.s7.empty() ? nullptr : L.s7.data()),
        f(L.f.data()),
        st{L.st[0], L.st[1], L.st[2]} {
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

// Calls f(q, p) for every interior cell of a range in storage order (q interior, p ghosted).
template <class F>
inline void for_cells(const Level& L, const Range& R, F&& f) {
  const GridShape& s = L.shape;
  for (int k = R.k0; k < R.k1; ++k)
    for (int j = R.j0; j < R.j1; ++j) {
      std::size_t q = L.cell(0, j, k);
      std::ptrdiff_t p = L.at(0, j, k);
      for (int i = 0; i < s.n[0]; ++i, ++q, ++p) f(q, p);
    }
}
template <class F>
inline void dispatch(int dimension, F&& f) {
  if (dimension == 1)
    f(std::integral_constant<int, 1>{});
  else if (dimension == 2)
    f(std::integral_constant<int, 2>{});
  else
    f(std::integral_constant<int, 3>{});
}

}  // namespace remnant::xcfc
