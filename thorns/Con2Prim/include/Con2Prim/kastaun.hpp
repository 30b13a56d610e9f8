#pragma once
// Steps (ii)-(v) of the paper's recovery (Kastaun et al. 2021 adapted to tabulated EOS), for any EOS
// type of the EOS thorn. Notation of the paper: q = tau/D, r_i = S_i/D, B^i/sqrt(D) (written Bc here),
// chi = 1/(1 + mu Bc^2), mu = 1/(hW).
//
// One correction to the paper's text: its Eq. for v0 prints r^2/(h_min^2 + r^2), which is v0^2 in
// Kastaun et al. (v0 = z0/sqrt(1 + z0^2), z0 = r/h_min); v_hat^2 is limited by that v0^2.
#include <algorithm>
#include <cmath>

#include "Con2Prim/master_eos.hpp"
#include "Con2Prim/root_finding.hpp"
#include "Con2Prim/root_solution.hpp"
#include "Con2Prim/settings.hpp"
#include "Con2Prim/state.hpp"
#include "EOS/tabulated_at_ye.hpp"
#include "EOS/types.hpp"

namespace remnant::con2prim {

template <class E>
class KastaunSolver {
 public:
  using Eval = MasterEval;

  // T_hint: MasterEos's search hint for the first evaluation (0: none).
  KastaunSolver(const E& eos, const Settings& s, const Metric3& g, const Conserved& c, double ye, double T_hint = 0)
      : thermo_(eos, s.eps_to_T, ye, T_hint), D_(c.D) {
    const double invD = 1 / c.D;
    q_ = c.tau * invD;
    for (int i = 0; i < 3; ++i) r_low_[i] = c.S[i] * invD;
    r_up_ = g.raise(r_low_);
    r2_ = dot(r_low_, r_up_);
    const double isD = std::sqrt(invD);
    for (int i = 0; i < 3; ++i) Bc_[i] = c.B[i] * isD;
    Bc2_ = g.norm2_up(Bc_);
    rB_ = dot(r_low_, Bc_);
    rperp2_Bc2_ = std::max(0.0, r2_ * Bc2_ - rB_ * rB_);  // r_perp^2 Bc^2
    h_min_ = thermo_.bounds().h_min;
    v0sq_ = r2_ / (h_min_ * h_min_ + r2_);
    // 1 - v0^2, exactly h_min^2 / (h_min^2 + r^2) where the subtraction would round to 0 (r above
    // ~1e8 h_min, e.g. W = 1e6 with a hot gas): W stays finite at the cap.
    one_minus_v0sq_ = 1 - v0sq_;
    if (!(one_minus_v0sq_ > 0)) one_minus_v0sq_ = h_min_ * h_min_ / (h_min_ * h_min_ + r2_);
  }

  // r_bar^2(mu) = r^2 chi^2 + mu chi (1 + chi) (r.Bc)^2.
  double rbar2(double mu, double chi) const { return r2_ * chi * chi + mu * chi * (1 + chi) * rB_ * rB_; }

  // Auxiliary function f_a(mu) = mu sqrt(h_min^2 + rbar^2) - 1 and its derivative; no EOS call.
  // d(rbar^2)/dmu = -2 chi^3 r_perp^2 Bc^2, so f_a' > 0: the root mu_+ is unique.
  void aux(double mu, double& f, double& df) const {
    const double chi = 1 / (1 + mu * Bc2_);
    const double s = std::sqrt(h_min_ * h_min_ + rbar2(mu, chi));
    f = mu * s - 1;
    df = s - mu * chi * chi * chi * rperp2_Bc2_ / s;
  }

  // Master function f(mu) = mu - 1/(max(nu_A, nu_B) + mu rbar^2), in the paper's order of steps.
  Eval operator()(double mu) {
    Eval e;
    e.x = mu;
    const double chi = 1 / (1 + mu * Bc2_);
    const double rb2 = rbar2(mu, chi);
    const double qbar = q_ - 0.5 * Bc2_ - 0.5 * mu * mu * chi * chi * rperp2_Bc2_;
    const double v2 = std::min(mu * mu * rb2, v0sq_);
    const double inv_W = std::sqrt(v2 < v0sq_ ? 1 - v2 : one_minus_v0sq_);
    const double W = 1 / inv_W;
    // Tables: products, not quotients, on the chain to the EOS (analytic EOS keep their bits).
    const double rho0 = kTabulated ? D_ * inv_W : D_ / W;
    const double eps0 = W * (qbar - mu * rb2) + v2 * W * W / (1 + W);
    // eps clamped to [eps_low(rho, Ye), eps_high(rho, Ye)] and T from eps, guessed from the last call.
    const auto t = thermo_.evaluate(W, rho0, eps0, e);
    const double a = t.press / (t.rho * (1 + e.eps));
    const double nuA = kTabulated ? (1 + a) * (1 + e.eps) * inv_W : (1 + a) * (1 + e.eps) / W;
    const double nuB = (1 + a) * (1 + qbar - mu * rb2);
    e.f = mu - 1 / (std::max(nuA, nuB) + mu * rb2);
    thermo_.rate_last(e.f);
    return e;
  }

  // (iii) mu_+ by Newton on f_a in (0, 1/h_min] (f_a(1/h_min) >= 0 always), and the ends of the
  // bracket (0, mu_+], with a round-off margin above mu_+ (f(mu_+) >= 0 in exact arithmetic).
  // False when f does not change sign on it.
  bool bracket(Eval& lo, Eval& hi, RootSolution& out) {
    upper_end(hi, out);
    lo = (*this)(0.0);
    return hi.f >= 0 && lo.f <= 0;
  }
  void upper_end(Eval& hi, RootSolution& out) {
    const double mu_max = 1 / h_min_;
    hi = (*this)(std::min(mu_max, mu_plus(out) * (1 + 1e-12)));
    if (hi.f < 0 && hi.x < mu_max) hi = (*this)(mu_max);
  }
  double mu_plus(RootSolution& out) const {
    RootStats aux_stats;
    // Start at 1/sqrt(h_min^2 + r^2): the root without a field, and a lower bound of mu_+ with one
    // (r_bar^2 <= r^2 since it falls with mu from r^2 at mu = 0).
    const double mu_0 = kTabulated ? 1 / std::sqrt(h_min_ * h_min_ + r2_) : NAN;  // analytic: their bits
    const double mu = newton_bracketed([&](double m, double& f, double& df) { aux(m, f, df); }, 0.0, 1 / h_min_,
                                       1e-14, 60, aux_stats, mu_0);
    out.aux_iterations = aux_stats.iterations;
    return mu;
  }

  // A nearer upper end than mu_+ without an EOS call, where p >= 0 and eps > -1 (so a >= 0):
  // nu + mu rbar^2 >= 1 + qbar(mu) (nu >= nu_B = (1 + a)(1 + qbar - mu rbar^2) when that bracket is
  // >= 0, else nu >= nu_A > 0 > 1 + qbar - mu rbar^2), hence f(mu) >= mu - 1/(1 + qbar(mu)); qbar
  // falls with mu, so f >= 0 on [1/(1 + qbar(mu_+)), mu_+]. The root (every root) lies below that
  // end, which is closer to it than mu_+ (without a field: by p/(rho h W^2) against about
  // (h^2 - h_min^2)/(2 h^2 W^2); 4.8 times closer on average over random SFHo states, test
  // Con2PrimRoots.TabulatedUpperEnd*). Returns mu_plus where the bound does not apply.
  double mu_upper(double mu_plus) const {
    const eos::Bounds& b = thermo_.bounds();
    if (!(b.press_min >= 0 && b.eps_min > -1)) return mu_plus;
    const double chi = 1 / (1 + mu_plus * Bc2_);
    const double one_qbar = 1 + q_ - 0.5 * Bc2_ - 0.5 * mu_plus * mu_plus * chi * chi * rperp2_Bc2_;
    if (!(one_qbar > 0)) return mu_plus;
    return std::min(mu_plus, 1 / one_qbar);
  }

  // The same bracket, narrowed for the root finder: f(mu) = mu - g(mu), and the fixed-point image
  // g(mu_hi) = mu_hi - f(mu_hi) of the upper end lies below the root wherever g decreases (the usual
  // case: f >= 0 there is checked, not assumed). Then it is the lower end, in place of mu = 0, and
  // usually near the root; otherwise it is the new upper end and mu = 0 the lower one.
  // prior: an evaluation made here that is neither end (the upper end replaced by a nearer one), for
  // Brent's first step (brent_root); prior.x = NAN when there is none.
  // nearer = false: from mu_+ as before issue 21 (the recovery's fallback where the root reached from
  // the nearer end does not reproduce the conserved variables: recover.hpp).
  bool narrow_bracket(Eval& lo, Eval& hi, Eval& prior, RootSolution& out, bool nearer = true) {
    prior.x = NAN;
    const double mu_p = mu_plus(out), mu_u = nearer ? mu_upper(mu_p) : mu_p;
    if (mu_u < mu_p) {
      hi = (*this)(mu_u * (1 + 1e-12));
      if (!(hi.f >= 0)) upper_end(hi, out);  // round-off where the bound is tight: mu_+ as before
    } else {
      upper_end(hi, out);
    }
    if (!(hi.f >= 0)) return false;
    const double mu1 = hi.x - hi.f;
    if (mu1 > 0 && mu1 < hi.x) {
      const Eval m = (*this)(mu1);
      if (m.f <= 0) return lo = m, true;
      if (m.f > 0) {
        // g increases here: the secant through both points, stepped a little beyond, for the lower end.
        const Eval h0 = hi;
        hi = m;
        if (m.f < h0.f) {
          const double step = m.f * (h0.x - m.x) / (h0.f - m.f);
          const double mu2 = m.x - 1.25 * step;
          if (mu2 > 0 && mu2 < m.x) {
            const Eval m2 = (*this)(mu2);
            if (m2.f <= 0) return lo = m2, prior = h0, true;
            if (m2.f > 0) hi = m2;
          }
        }
      }
    }
    lo = (*this)(0.0);
    return lo.f <= 0;
  }

  // The solution at a root (with the far end of its final bracket, for the secant polish).
  RootSolution solution(Eval root, const Eval& far, const RootStats& st, const Settings& s, RootSolution out) {
    if (s.secant_polish) root = secant_polish(root, far);
    out.iterations = st.iterations;
    out.converged = st.converged;
    out.early_stop = st.early;
    out.evaluations = thermo_.evaluations();
    // (v) velocity from the root, v^i = mu chi (r^i + mu (r.Bc) Bc^i), at the speed of its W.
    const double mu = root.x, chi = 1 / (1 + mu * Bc2_);
    for (int i = 0; i < 3; ++i) out.v[i] = mu * chi * (r_up_[i] + mu * rB_ * Bc_[i]);
    copy_root_state(root, out);
    return out;
  }

  // early_stop (tables): Brent may stop one evaluation before closing its bracket (root_finding.hpp);
  // RootSolution::early_stop says it did, and the pipeline solves again without it where the result
  // does not reproduce the conserved variables to the root tolerance.
  RootSolution solve(const Settings& s, bool early_stop = true, bool nearer_start = true) {
    RootSolution out;
    Eval lo, hi, prior;
    prior.x = NAN;
    // (iv) Brent on the bracket (narrowed for tables, where an evaluation costs a table search;
    // analytic EOS keep the bits that the regression suites hold).
    if (!(kTabulated ? narrow_bracket(lo, hi, prior, out, nearer_start) : bracket(lo, hi, out))) {
      out.bracketed = out.converged = false;
      out.evaluations = thermo_.evaluations();
      return out;
    }
    Eval root, far;
    RootStats st = brent_root(*this, lo, hi, s.tolerance, s.max_iterations, root, far,
                              kTabulated && early_stop ? kEarlyStop : 0.0,
                              std::isnan(prior.x) || !nearer_start ? nullptr : &prior);
    if (root.inv_flags & eos::kInvBelowEpsLow) {
      // Raising eps to eps_low(rho) (rule 8) can add a root beside the physical one where the table's
      // cold eps grows fast with rho (LS220 above ~5e15 g/cm^3): prefer an unclamped root below it.
      Eval root2, far2;
      RootStats st2;
      if (unclamped_root_below(lo.x == 0 ? lo : (*this)(0.0), root.x, s, st2, root2, far2)) {
        root = root2, far = far2;
        st.converged = st2.converged;
        st.early = st2.early;
        st.iterations += st2.iterations;
      }
    }
    return solution(root, far, st, s, out);
  }

  // eps_hat_0(mu) below eps_low(rho_hat(mu), Ye), i.e. rule 8 clamps there (one EOS inversion).
  bool clamped_low(double mu) const {
    const double chi = 1 / (1 + mu * Bc2_);
    const double rb2 = rbar2(mu, chi);
    const double qbar = q_ - 0.5 * Bc2_ - 0.5 * mu * mu * chi * chi * rperp2_Bc2_;
    const double v2 = std::min(mu * mu * rb2, v0sq_);
    const double W = 1 / std::sqrt(v2 < v0sq_ ? 1 - v2 : one_minus_v0sq_);
    const double eps0 = W * (qbar - mu * rb2) + v2 * W * W / (1 + W);
    return (thermo_.inversion_flags(D_ / W, eps0) & eos::kInvBelowEpsLow) != 0;
  }

  // The clamped region [mu_c, root] found by bisection on clamped_low; if f > 0 just below mu_c,
  // the physical root lies in (0, mu_c): Brent there. False when mu = 0 is clamped too or f < 0.
  bool unclamped_root_below(const Eval& lo, double mu_root, const Settings& s, RootStats& st, Eval& root,
                            Eval& far) {
    if (lo.inv_flags & eos::kInvBelowEpsLow) return false;
    double a = lo.x, b = mu_root;
    for (int k = 0; k < 16; ++k) {
      const double m = 0.5 * (a + b);
      (clamped_low(m) ? b : a) = m;
    }
    const Eval edge = (*this)(a);
    if (edge.f < 0 || (edge.inv_flags & eos::kInvBelowEpsLow)) return false;
    st = brent_root(*this, lo, edge, s.tolerance, s.max_iterations, root, far);
    return true;
  }

  // True when every mu in [a.x, b.x] evaluates with eps clamped by rule 9 (eps_hat(mu) >= eps_high(
  // rho_hat(mu)) = eps(rho_hat, T_max, Ye)), proven from a and b, both clamped so, without an EOS
  // call: a root there is never accepted (rule 9 moves the state), so a root scan may skip the
  // samples in between (root_scan.hpp). With v_hat^2 = mu^2 rbar^2 below v0^2 (uncapped),
  // eps_hat = W (1 + qbar - mu rbar^2) - 1, where W rises with mu (mu^2 rbar^2 does), qbar falls
  // (mu chi rises) and mu rbar^2 <= r^2 mu_b chi_a^2 + (r.Bc)^2 mu_b^2 chi_a (1 + chi_a) (chi falls):
  // a lower bound of eps_hat. rho_hat = D/W falls with mu; between the table's rho nodes
  // eps_high(rho) is monotonic, so its largest value is a's or b's clamped eps or a node's.
  bool clamped_high_between(const Eval& a, const Eval& b) const {
    if constexpr (!kTabulated) return false;
    constexpr std::uint32_t other = eos::kInvBelowEpsLow | eos::kInvRhoClamped | eos::kInvMaxIter;
    if (!(a.inv_flags & b.inv_flags & eos::kInvAboveEpsHigh) || ((a.inv_flags | b.inv_flags) & other)) return false;
    const double mu_a = a.x, mu_b = b.x;
    const double chi_a = 1 / (1 + mu_a * Bc2_), chi_b = 1 / (1 + mu_b * Bc2_);
    if (!(mu_b * mu_b * rbar2(mu_b, chi_b) < v0sq_)) return false;  // v_hat^2 capped: W fixed there
    const double qbar_b = q_ - 0.5 * Bc2_ - 0.5 * mu_b * mu_b * chi_b * chi_b * rperp2_Bc2_;
    const double mu_rbar2_max = r2_ * mu_b * chi_a * chi_a + rB_ * rB_ * mu_b * mu_b * chi_a * (1 + chi_a);
    const double X = 1 + qbar_b - mu_rbar2_max;
    const double eps_hat_min = std::min(a.W * X, b.W * X) - 1;
    const double ends_max = std::max(a.eps, b.eps);
    // Round-off of both sides (a few ulps of W X and of the table's exp) well inside this margin.
    const double margin = 1e-10 * (std::abs(b.W * X) + std::abs(ends_max) + 1);
    if (!(eps_hat_min > ends_max + margin)) return false;
    const double nodes_max = thermo_.eps_high_between(a.rho0, b.rho0);
    return nodes_max == -INFINITY || eps_hat_min > nodes_max + 1e-10 * (std::abs(b.W * X) + std::abs(nodes_max) + 1);
  }

  // For the rescaling of v when v_hat^2 hit v0^2 (done by the pipeline through match_speed_to_W).
  double v0_squared() const { return v0sq_; }

 private:
  static constexpr bool kTabulated = eos::is_tabulated_v<E>;
  // Brent's early stop: the predicted step at most 1/16 of the tolerance.
  static constexpr double kEarlyStop = 1.0 / 16;
  MasterEos<E> thermo_;
  double D_;
  double q_ = 0, r2_ = 0, Bc2_ = 0, rB_ = 0, rperp2_Bc2_ = 0, h_min_ = 1, v0sq_ = 0, one_minus_v0sq_ = 1;
  Vec3 r_low_{}, r_up_{}, Bc_{};
};

}  // namespace remnant::con2prim
