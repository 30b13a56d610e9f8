#pragma once
// Cold (T = 0) polytrope p = K rho^Gamma, possibly piecewise: barotropic, for initial data.
// Given (rho, eps), eps is replaced by the cold eps(rho) (flagged as rule 8 or 9).
#include <cstdint>

#include "EOS/counter.hpp"
#include "EOS/piecewise_polytrope.hpp"
#include "EOS/types.hpp"

namespace remnant::eos {

template <class Counter = NoCount>
class Polytrope {
 public:
  static constexpr bool has_temperature = false;
  Polytrope(double K, double gamma, Bounds b = {}) : Polytrope(PiecewisePolytrope(K, {gamma}, {}), b) {}
  explicit Polytrope(PiecewisePolytrope pp, Bounds b = {}) : pp_(std::move(pp)), b_(b) {
    b_.T_min = b_.T_max = 0;
    b_.eps_min = pp_.eps(b_.rho_min);
    b_.eps_max = std::isfinite(b_.rho_max) ? pp_.eps(b_.rho_max) : Bounds::inf;
    b_.h_min = 1 + b_.eps_min + pp_.press(b_.rho_min) / std::max(b_.rho_min, 1e-300);
    if (!(b_.rho_min > 0)) b_.h_min = 1;
  }
  const PiecewisePolytrope& cold() const { return pp_; }
  const Bounds& bounds() const { return b_; }
  bool has_chemical_potentials() const { return false; }
  bool has_composition() const { return false; }
  const Counter& counter() const { return c_; }

  Thermo thermo(double rho, double /*T*/ = 0, double /*ye*/ = 0) const {
    c_.add();
    Thermo o;
    double dp;
    pp_.eval(rho, o.press, o.eps, dp);
    o.h = 1 + o.eps + o.press / rho;
    o.cs2 = dp / o.h;
    return o;
  }
  double press(double rho, double = 0, double = 0) const { c_.add(); return pp_.press(rho); }
  double eps(double rho, double = 0, double = 0) const { c_.add(); return pp_.eps(rho); }

  Inversion temperature(double rho, double eps, double, double = 0, InversionMethod = InversionMethod::exact) const {
    Inversion r;
    r.eps = this->eps(rho);
    r.T = 0;
    if (eps < r.eps) r.flags |= kInvBelowEpsLow;
    if (eps > r.eps) r.flags |= kInvAboveEpsHigh;
    return r;
  }
  Thermo thermo_from_eps(double rho, double eps, double ye, double& T_guess, std::uint32_t* flags = nullptr,
                         InversionMethod = InversionMethod::exact) const {
    if (flags) *flags = temperature(rho, eps, ye).flags;
    T_guess = 0;
    return thermo(rho);
  }

 private:
  PiecewisePolytrope pp_;
  Bounds b_;
  [[no_unique_address]] Counter c_;
};

}  // namespace remnant::eos
