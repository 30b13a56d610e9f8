#pragma once
// The comparison method: the 1D recovery of Palenzuela et al. 2015 in the form of Siegel et al. 2018,
// on the same EOS and the same eps -> T inversion. Unknown x = h W; with q = tau/D, r = S^2/D^2,
// s = B^2/D, t = B.S/D^(3/2):
//   W^-2 = 1 - [x^2 r + (2x + s) t^2] / [x^2 (x + s)^2],
//   eps  = -1 + (x/W)(1 - W^2) + W [1 + q - s + (s/W^2 + t^2/x^2)/2],
//   f(x) = x - h(rho = D/W, eps, Ye) W,
// solved by Brent on [1 + q - s, 2 + 2q - s] (widened when it does not bracket the root).
#include <algorithm>
#include <cmath>
#include <limits>

#include "Con2Prim/master_eos.hpp"
#include "Con2Prim/root_finding.hpp"
#include "Con2Prim/root_solution.hpp"
#include "Con2Prim/settings.hpp"
#include "Con2Prim/state.hpp"
#include "EOS/types.hpp"

namespace remnant::con2prim {

template <class E>
class PalenzuelaSolver {
 public:
  using Eval = MasterEval;

  // T_hint: MasterEos's search hint for the first evaluation (0: none).
  PalenzuelaSolver(const E& eos, const Settings& s, const Metric3& g, const Conserved& c, double ye,
                   double T_hint = 0)
      : thermo_(eos, s.eps_to_T, ye, T_hint), g_(g), c_(c) {
    const double invD = 1 / c.D;
    q_ = c.tau * invD;
    r_ = g.norm2_down(c.S) * invD * invD;
    s_ = g.norm2_up(c.B) * invD;
    t_ = dot(c.S, c.B) * invD * std::sqrt(invD);
  }

  Eval operator()(double x) {
    constexpr double kMaxV2 = 1 - 4 * std::numeric_limits<double>::epsilon();
    Eval e;
    e.x = x;
    const double x2 = x * x, xs = x + s_;
    const double v2 = std::clamp((x2 * r_ + (2 * x + s_) * t_ * t_) / (x2 * xs * xs), 0.0, kMaxV2);
    const double W = 1 / std::sqrt(1 - v2);
    const double rho0 = c_.D / W;
    const double eps0 = -1 + x / W * (1 - W * W) + W * (1 + q_ - s_ + 0.5 * (s_ / (W * W) + t_ * t_ / x2));
    const auto th = thermo_.evaluate(W, rho0, eps0, e);
    const double h = 1 + e.eps + th.press / th.rho;
    e.f = x - h * W;
    thermo_.rate_last(e.f);
    return e;
  }

  // [1 + q - s, 2 + 2q - s], widened until f changes sign; false if it never does.
  bool bracket(Eval& lo, Eval& hi, RootSolution&) {
    const double floor = 0.5 * thermo_.bounds().h_min;  // x = h W >= h_min
    lo = (*this)(std::max(1 + q_ - s_, floor));
    hi = (*this)(std::max(2 + 2 * q_ - s_, 2 * lo.x));
    for (int k = 0; k < 60 && lo.f > 0 && lo.x > floor; ++k) lo = (*this)(std::max(0.5 * lo.x, floor));
    for (int k = 0; k < 60 && hi.f < 0; ++k) hi = (*this)(2 * hi.x);
    return lo.f <= 0 && hi.f >= 0;
  }

  RootSolution solve(const Settings& s) {
    RootSolution out;
    Eval lo, hi;
    if (!bracket(lo, hi, out)) {
      out.bracketed = out.converged = false;
      out.evaluations = thermo_.evaluations();
      return out;
    }
    Eval root, far;
    const RootStats st = brent_root(*this, lo, hi, s.tolerance, s.max_iterations, root, far);
    return solution(root, far, st, s, out);
  }

  RootSolution solution(Eval root, const Eval& far, const RootStats& st, const Settings& s, RootSolution out) {
    if (s.secant_polish) root = secant_polish(root, far);
    out.iterations = st.iterations;
    out.converged = st.converged;
    out.evaluations = thermo_.evaluations();
    // v_i = (S_i + (B.S) B_i / z) / (z + B^2), z = D x = rho h W^2.
    const double z = c_.D * root.x, B2 = g_.norm2_up(c_.B), BS = dot(c_.S, c_.B);
    const Vec3 B_low = g_.lower(c_.B);
    Vec3 v_low;
    for (int i = 0; i < 3; ++i) v_low[i] = (c_.S[i] + BS * B_low[i] / z) / (z + B2);
    out.v = g_.raise(v_low);
    copy_root_state(root, out);
    return out;
  }

 private:
  MasterEos<E> thermo_;
  const Metric3& g_;
  const Conserved& c_;
  double q_ = 0, r_ = 0, s_ = 0, t_ = 0;
};

}  // namespace remnant::con2prim
