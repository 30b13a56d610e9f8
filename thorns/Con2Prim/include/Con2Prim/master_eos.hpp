#pragma once
// The EOS side of one master-function evaluation, shared by the recovery methods (Kastaun,
// Palenzuela): rho = D/W clamped to the table, T from eps (guessed from the previous evaluation,
// eps clamped by the inversion's rules 8/9), the pressure, and the count of evaluations.
#include <algorithm>
#include <cstdint>

#include "Con2Prim/root_solution.hpp"
#include "EOS/types.hpp"

namespace remnant::con2prim {

template <class E>
class MasterEos {
 public:
  MasterEos(const E& eos, eos::InversionMethod method, double ye)
      : eos_(eos), b_(eos.bounds()), method_(method), ye_(ye) {}

  const eos::Bounds& bounds() const { return b_; }
  int evaluations() const { return evaluations_; }

  struct Thermo {
    double rho, press;  // rho clamped to the table
  };
  // Fills e.W, e.rho0 (unclamped D/W), e.eps, e.T and e.inv_flags; counts one evaluation.
  Thermo evaluate(double W, double rho0, double eps0, MasterEval& e) {
    const double rho = std::clamp(rho0, b_.rho_min, b_.rho_max);
    const eos::Inversion inv = eos_.temperature(rho, eps0, ye_, T_guess_, method_);
    T_guess_ = inv.T;
    e.W = W;
    e.rho0 = rho0;
    e.eps = inv.eps;
    e.T = inv.T;
    e.inv_flags = inv.flags;
    ++evaluations_;
    return {rho, eos_.press(rho, inv.T, ye_)};
  }
  // The inversion's flags at (rho0, eps0) without counting or moving the guess.
  std::uint32_t inversion_flags(double rho0, double eps0) const {
    return eos_.temperature(std::clamp(rho0, b_.rho_min, b_.rho_max), eps0, ye_, T_guess_, method_).flags;
  }

 private:
  const E& eos_;
  const eos::Bounds& b_;
  eos::InversionMethod method_;
  double ye_;
  double T_guess_ = 0;  // none yet
  int evaluations_ = 0;
};

// The root's state into the solution (the velocity is the method's own).
inline void copy_root_state(const MasterEval& root, RootSolution& out) {
  out.W = root.W;
  out.rho = root.rho0;
  out.eps = root.eps;
  out.T = root.T;
  out.inversion_flags = root.inv_flags;
}

}  // namespace remnant::con2prim
