#pragma once
// The EOS side of one master-function evaluation, shared by the recovery methods (Kastaun,
// Palenzuela): rho = D/W clamped to the table, T from eps (guessed from the previous evaluation,
// eps clamped by the inversion's rules 8/9), the pressure, and the count of evaluations.
// A table with the exact inversion goes through eos::TabulatedAtYe (Ye's index and weight found once
// per recovery; T and p from one column read, usually one table call per evaluation).
#include <algorithm>
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
  MasterEos(const E& eos, eos::InversionMethod method, double ye)
      : eos_(eos), b_(eos.bounds()), method_(method), ye_(ye), slice_(make_slice(eos, ye)) {}

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
        // nearest to the root so far.
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
