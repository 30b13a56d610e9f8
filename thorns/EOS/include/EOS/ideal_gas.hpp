#pragma once
// Ideal gas (Gamma-law): p = (Gamma - 1) rho eps, with T = (Gamma - 1) m_b eps (T, m_b in MeV),
// i.e. p = n T. Ye is carried but does not enter. eps_low = 0 (T = 0) plays rule 8's role.
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "EOS/counter.hpp"
#include "EOS/errors.hpp"
#include "EOS/types.hpp"
#include "EOS/units.hpp"

namespace remnant::eos {

template <class Counter = NoCount>
class IdealGas {
 public:
  static constexpr bool has_temperature = true;
  explicit IdealGas(double gamma, double baryon_mass_MeV = units::neutron_mass_MeV, Bounds b = {})
      : g_(gamma), mb_(baryon_mass_MeV), b_(b) {
    if (!(gamma > 1)) throw EosError("ideal gas: Gamma must be > 1, got " + std::to_string(gamma));
    if (!(baryon_mass_MeV > 0)) throw EosError("ideal gas: the baryon mass must be > 0");
    b_.eps_min = std::max(0.0, b_.T_min / ((g_ - 1) * mb_));
    b_.eps_max = b_.T_max / ((g_ - 1) * mb_);
    b_.h_min = 1 + g_ * b_.eps_min;
    b_.press_min = 0;
  }
  double gamma() const { return g_; }
  // Entropy index ln(p / rho^Gamma) / (Gamma - 1): constant along adiabats (not in Thermo: the
  // evolution's EOS calls would pay a log and a pow each).
  double entropy_index(double rho, double eps) const {
    const double p = (g_ - 1) * rho * eps;
    return p > 0 ? std::log(p / std::pow(rho, g_)) / (g_ - 1) : 0.0;
  }
  const Bounds& bounds() const { return b_; }
  bool has_chemical_potentials() const { return false; }
  bool has_composition() const { return false; }
  const Counter& counter() const { return c_; }

  Thermo thermo(double rho, double T, double /*ye*/) const { return from_eps(rho, T / ((g_ - 1) * mb_)); }
  double press(double rho, double T, double ye) const { return thermo(rho, T, ye).press; }
  double eps(double, double T, double) const { c_.add(); return T / ((g_ - 1) * mb_); }

  Inversion temperature(double rho, double eps, double /*ye*/, double = 0,
                        InversionMethod = InversionMethod::exact) const {
    Inversion r;
    r.eps = eps;
    if (!(rho >= b_.rho_min && rho <= b_.rho_max)) r.flags |= kInvRhoClamped;
    if (!(eps > b_.eps_min)) r.eps = b_.eps_min, r.flags |= kInvBelowEpsLow;
    else if (eps >= b_.eps_max) r.eps = b_.eps_max, r.flags |= kInvAboveEpsHigh;
    r.T = (g_ - 1) * mb_ * r.eps;
    return r;
  }
  Thermo thermo_from_eps(double rho, double eps, double ye, double& T_guess, std::uint32_t* flags = nullptr,
                         InversionMethod = InversionMethod::exact) const {
    const Inversion inv = temperature(rho, eps, ye);
    T_guess = inv.T;
    if (flags) *flags = inv.flags;
    return from_eps(rho, inv.eps);
  }

 private:
  Thermo from_eps(double rho, double eps) const {
    c_.add();
    Thermo o;
    o.eps = eps;
    o.press = (g_ - 1) * rho * eps;
    o.h = 1 + eps + o.press / rho;
    o.cs2 = g_ * o.press / (rho * o.h);
    return o;
  }
  double g_, mb_;
  Bounds b_;
  [[no_unique_address]] Counter c_;
};

}  // namespace remnant::eos
