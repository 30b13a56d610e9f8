#pragma once
// Root finders of the recovery. Brent carries the whole evaluation record (not just f), so that the
// state at the returned root is known without evaluating the master function once more; it stops on a
// relative bracket width. Newton with a bisection safeguard solves the EOS-free auxiliary function.
#include <algorithm>
#include <cmath>
#include <limits>

namespace remnant::con2prim {

struct RootStats {
  int iterations = 0;
  bool converged = false;
  bool early = false;  // stopped by early_stop (the bracket was not closed)
};

// Brent's method on [a.x, b.x] with a.f, b.f of opposite sign (or one zero). Eval has members x, f
// and rel_change(other): the largest relative difference of the quantities the caller cares about
// (W, eps). eval(x) returns an Eval. The x tolerance is rel_tol |b.x| divided by the sensitivity
// of those quantities to x, estimated by the secant across the bracket, so that the stop means
// "W, eps (and x) known to rel_tol"; it never goes below round-off. `best` receives the record of b,
// `other` that of the far end c of the final bracket (for secant_polish).
//
// early_stop > 0: also stop when an accepted interpolation step from b is at most early_stop * tol
// and at most 1e-3 of the step before (b already that close to the root on the superlinear model),
// instead of one more evaluation a tolerance step across the root to close the bracket. Not a
// guarantee: the caller checks the result (recover.hpp) and solves again without it where needed.
//
// prior (optional): a third evaluation already made outside the bracket (the caller's bracket search),
// taken as Brent's previous iterate so that the first step interpolates through all three points
// (inverse quadratic) instead of the secant of the two ends: one evaluation fewer on smooth functions.
// It must differ from both ends in x and f; otherwise it is ignored.
template <class Eval, class F>
RootStats brent_root(F&& eval, Eval a_in, Eval b_in, double rel_tol, int max_iter, Eval& best, Eval& other,
                     double early_stop = 0, const Eval* prior = nullptr) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  RootStats st;
  if (a_in.f == 0) return best = other = a_in, st.converged = true, st;
  if (b_in.f == 0) return best = other = b_in, st.converged = true, st;
  // The records stay where they are (72 bytes each): a, b, c point into three slots, of which b and c
  // use at most two, so a new evaluation always has a free one. Same arithmetic as copying them.
  Eval spare;
  const Eval* a = &a_in;
  const Eval* b = &b_in;
  const Eval* c = a;
  double d = b->x - a->x, e = d;
  bool fresh = false;  // a is the prior point, c the other end: skip the first reset of c
  if (prior && (a_in.f > 0) != (b_in.f > 0) && prior->x != a_in.x && prior->x != b_in.x &&
      prior->f != a_in.f && prior->f != b_in.f) {
    if (std::abs(a_in.f) < std::abs(b_in.f)) b = &a_in, c = &b_in;
    else c = &a_in;
    a = prior;
    d = e = b->x - a->x;
    fresh = true;
  }
  for (int it = 0;; ++it) {
    if (fresh) {
      fresh = false;
    } else if ((b->f > 0) == (c->f > 0)) {  // keep the root between b and c
      c = a;
      d = e = b->x - a->x;
    }
    if (std::abs(c->f) < std::abs(b->f)) {  // b is the best estimate
      a = b, b = c, c = a;
    }
    const double dx_rel = std::abs(c->x - b->x) / std::abs(b->x);
    const double sensitivity = dx_rel > 0 ? b->rel_change(*c) / dx_rel : 0.0;
    // A quarter: the bracket (not just the step) ends below rel_tol / 2 in every quantity.
    const double tol = 2 * kEps * std::abs(b->x) + 0.25 * rel_tol * std::abs(b->x) / std::max(1.0, sensitivity);
    const double m = 0.5 * (c->x - b->x);
    if (std::abs(m) <= tol || b->f == 0) {
      st.iterations = it;
      st.converged = true;
      best = *b, other = *c;
      return st;
    }
    if (it == max_iter) {
      st.iterations = it;
      best = *b, other = *c;
      return st;
    }
    if (std::abs(e) >= tol && std::abs(a->f) > std::abs(b->f)) {
      double p, q;
      const double s = b->f / a->f;
      if (a->x == c->x) {  // secant
        p = 2 * m * s;
        q = 1 - s;
      } else {  // inverse quadratic interpolation
        const double qq = a->f / c->f, rr = b->f / c->f;
        p = s * (2 * m * qq * (qq - rr) - (b->x - a->x) * (rr - 1));
        q = (qq - 1) * (rr - 1) * (s - 1);
      }
      if (p > 0) q = -q;
      else p = -p;
      if (2 * p < std::min(3 * m * q - std::abs(tol * q), std::abs(e * q))) {
        const double step = p / q;
        if (early_stop > 0 && std::abs(step) <= early_stop * tol && std::abs(step) <= 1e-3 * std::abs(d)) {
          st.iterations = it;
          st.converged = st.early = true;
          best = *b, other = *c;
          return st;
        }
        e = d;
        d = step;
      } else {
        d = e = m;
      }
    } else {
      d = e = m;
    }
    a = b;
    const double x_next = b->x + (std::abs(d) > tol ? d : (m > 0 ? tol : -tol));
    Eval* slot = &spare;  // the slot neither b (now a) nor c uses
    if (b != &a_in && c != &a_in) slot = &a_in;
    else if (b != &b_in && c != &b_in) slot = &b_in;
    *slot = eval(x_next);
    b = slot;
  }
}

// The root's state without another evaluation: the secant root of the final bracket [b, c], and
// every recorded quantity (Eval::lerp) interpolated linearly to it. Brent stops with the bracket below
// the tolerance; the secant point's error is second order in that width, so the state is accurate to
// round-off for the price of a few multiplications and no EOS call.
template <class Eval>
Eval secant_polish(const Eval& b, const Eval& c) {
  if (b.f == 0 || c.f == b.f || (b.f > 0) == (c.f > 0)) return b;
  const double t = std::clamp(b.f / (b.f - c.f), 0.0, 1.0);
  return Eval::lerp(b, c, t);
}

// Newton on an increasing function with a sign change on [lo, hi] (f(lo) < 0 <= f(hi)), starting at
// `start` (default hi); a step leaving the current bracket is replaced by bisection. fdf(x, f, df)
// fills f and f'.
template <class FDF>
double newton_bracketed(FDF&& fdf, double lo, double hi, double rel_tol, int max_iter, RootStats& st,
                        double start = NAN) {
  double x = start >= lo && start <= hi ? start : hi, f, df;
  for (int it = 1; it <= max_iter; ++it) {
    fdf(x, f, df);
    st.iterations = it;
    if (f == 0) break;
    if (f > 0) hi = x;
    else lo = x;
    double next = x - f / df;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - x) <= rel_tol * std::abs(next);
    x = next;
    if (done) {
      st.converged = true;
      return x;
    }
  }
  st.converged = f == 0;
  return x;
}

}  // namespace remnant::con2prim
