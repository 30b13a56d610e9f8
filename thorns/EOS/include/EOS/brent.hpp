#pragma once
// Brent's method (inverse quadratic interpolation, secant and bisection) on a bracket [a, b]
// with f(a), f(b) of opposite sign. Header-only so that the function inlines into hot loops.
#include <cmath>
#include <utility>

namespace remnant::eos {

struct BrentResult {
  double x = 0, fx = 0;
  int iterations = 0;
  bool converged = false;
};

// Stops when the bracket is below xtol (absolute) or f(x) == 0; at most max_iter evaluations.
template <class F>
inline BrentResult brent(F&& f, double a, double b, double fa, double fb, double xtol, int max_iter) {
  BrentResult r;
  if (fa == 0) return {a, fa, 0, true};
  if (fb == 0) return {b, fb, 0, true};
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 1; it <= max_iter; ++it) {
    if ((fb > 0) == (fc > 0)) {  // keep the root between b and c
      c = a, fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {  // b is the best estimate
      a = b, b = c, c = a;
      fa = fb, fb = fc, fc = fa;
    }
    const double tol = 2 * 1.1e-16 * std::abs(b) + 0.5 * xtol;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || fb == 0) return {b, fb, it - 1, true};
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      double p, q, s = fb / fa;
      if (a == c) {  // secant
        p = 2 * m * s;
        q = 1 - s;
      } else {  // inverse quadratic interpolation
        const double qq = fa / fc, rr = fb / fc;
        p = s * (2 * m * qq * (qq - rr) - (b - a) * (rr - 1));
        q = (qq - 1) * (rr - 1) * (s - 1);
      }
      if (p > 0) q = -q; else p = -p;
      if (2 * p < std::min(3 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b, fa = fb;
    b += std::abs(d) > tol ? d : (m > 0 ? tol : -tol);
    fb = f(b);
    r.iterations = it;
  }
  return {b, fb, max_iter, false};
}

}  // namespace remnant::eos
