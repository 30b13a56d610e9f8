#pragma once
// The EOS side of one master-function evaluation, shared by the recovery methods (Kastaun,
// Palenzuela): rho = D/W clamped to the table, T from eps (guessed from the previous evaluation,
// eps clamped by the inversion's rules 8/9), the pressure, and the count of evaluations.
// A table with the exact inversion goes through eos::TabulatedAtYe (Ye's index and weight found once
// per recovery; T and p from one column read, usually one table call per evaluation).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "Con2Prim/root_solution.hpp"
#include "EOS/tabulated_at_ye.hpp"
#include "EOS/types.hpp"

namespace remnant::con2prim {

template <class E>
class MasterEos {
 public:
  // T_hint (MeV; <= 0 or not finite: none): where the first evaluation's T search starts, e.g. the
  // cell's T from the previous step. Used only by the table's exact inversion in cells where eps rises
  // with T (unique result there), so it changes the cost, never the T found; elsewhere it is ignored.
  MasterEos(const E& eos, eos::InversionMethod method, double ye, double T_hint = 0)
      : eos_(eos), b_(eos.bounds()), method_(method), ye_(ye), slice_(make_slice(eos, ye)) {
    if constexpr (kSliced)
      if (T_hint > 0 && T_hint < INFINITY) {
        // The hint as the "best so far" at x = 0: the first evaluation (no last one, |x - last_x_| = inf)
        // starts there, and its rate_last replaces it; no extra work per evaluation.
        ln_T_best_ = approx_ln(T_hint);
        best_x_ = 0;
      }
  }
  // ln x to 5.4e-3 (x > 0 finite) from its exponent and a quadratic in the mantissa: about 10
  // instructions where libm's log takes 50, half of what the hint saves. The hint only picks where a
  // search starts, and the tables' T intervals are 0.1-0.3 wide in ln T.
  static double approx_ln(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const double m = std::bit_cast<double>((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL) - 1;  // [0, 1)
    const double e = double(int((bits >> 52) & 0x7ff) - 1023);
    return (e + m * (1 + 0.347 * (1 - m))) * 0.6931471805599453;
  }

  const eos::Bounds& bounds() const { return b_; }
  int evaluations() const { return evaluations_; }

  struct Thermo {
    double rho, press;  // rho clamped to the table
  };
  // Fills e.W, e.rho0 (unclamped D/W), e.eps, e.T and e.inv_flags; counts one evaluation.
  [[gnu::always_inline]] Thermo evaluate(double W, double rho0, double eps0, MasterEval& e) {
    const double rho = std::clamp(rho0, b_.rho_min, b_.rho_max);
    if constexpr (kSliced) {
      if (method_ == eos::InversionMethod::exact) {
        // Hint: the T of the nearer (in the master variable e.x) of the last evaluation and the one
        // nearest to the root so far (before the first evaluation: the caller's hint, if any).
        const bool use_best = std::abs(e.x - best_x_) < std::abs(e.x - last_x_);
        const auto r = slice_.invert(rho, eps0, ln_T_guess_, use_best ? ln_T_best_ : ln_T_guess_);
        ln_T_guess_ = r.lnT;
        last_x_ = e.x;
        e.W = W;
        e.rho0 = rho0;
        e.eps = r.eps;
        e.T = r.T;
        e.has_lnT = true;
        e.lnT = r.lnT;
        e.inv_flags = r.flags;
        ++evaluations_;
        return {rho, r.press};
      }
    }
    const eos::Inversion inv = eos_.temperature(rho, eps0, ye_, T_guess_, method_);
    T_guess_ = inv.T;
    if constexpr (kSliced) ln_T_guess_ = std::log(inv.T);
    e.W = W;
    e.rho0 = rho0;
    e.eps = inv.eps;
    e.T = inv.T;
    e.inv_flags = inv.flags;
    ++evaluations_;
    return {rho, eos_.press(rho, inv.T, ye_)};
  }
  // The master function's value at the last evaluation. Where eps rises with T (the result does not
  // depend on where the search starts) the search starts at the T of the last evaluation or of the one
  // nearest to the root so far (smallest |f|), whichever is nearer in the master variable: Brent's
  // next point lies by its best one, a root scan's by its last. The guess that selects among several
  // T (other cells) stays the last evaluation's T.
  void rate_last(double f) {
    if (!(std::abs(f) < best_abs_f_)) return;
    best_abs_f_ = std::abs(f);
    best_x_ = last_x_;
    ln_T_best_ = ln_T_guess_;
  }
  // The largest rule-9 threshold eps(rho_i, T_max, Ye) at the table's rho nodes strictly between
  // rho_a and rho_b (inside the table); +inf where unknown (no exact inversion on a table).
  double eps_high_between(double rho_a, double rho_b) const {
    if constexpr (kSliced)
      if (method_ == eos::InversionMethod::exact) return slice_.eps_high_between(rho_a, rho_b);
    return INFINITY;
  }
  // The inversion's flags at (rho0, eps0) without counting or moving the guess.
  std::uint32_t inversion_flags(double rho0, double eps0) const {
    double T_guess = T_guess_;
    if constexpr (kSliced)
      if (method_ == eos::InversionMethod::exact) T_guess = std::isfinite(ln_T_guess_) ? std::exp(ln_T_guess_) : 0.0;
    return eos_.temperature(std::clamp(rho0, b_.rho_min, b_.rho_max), eps0, ye_, T_guess, method_).flags;
  }

 private:
  static constexpr bool kSliced = eos::is_tabulated_v<E>;
  struct NoSlice {};
  using Slice = std::conditional_t<kSliced, eos::TabulatedAtYe<E>, NoSlice>;
  static Slice make_slice(const E& eos, double ye) {
    if constexpr (kSliced) return Slice(eos, ye);
    else return {};
  }

  const E& eos_;
  const eos::Bounds& b_;
  eos::InversionMethod method_;
  double ye_;
  double T_guess_ = 0;  // none yet
  double ln_T_guess_ = -INFINITY;
  double last_x_ = INFINITY, best_x_ = INFINITY, ln_T_best_ = -INFINITY, best_abs_f_ = INFINITY;
  [[no_unique_address]] Slice slice_;
  int evaluations_ = 0;
};

// The root's state into the solution (the velocity is the method's own).
inline void copy_root_state(const MasterEval& root, RootSolution& out) {
  out.W = root.W;
  out.rho = root.rho0;
  out.eps = root.eps;
  out.T = root.temperature();
  out.lnT = root.has_lnT && !(root.T > 0) ? root.lnT : NAN;
  out.inversion_flags = root.inv_flags;
}

}  // namespace remnant::con2prim
