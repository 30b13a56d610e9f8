#pragma once
// Hybrid EOS: cold piecewise polytrope plus an ideal-gas thermal part,
//   p = p_c(rho) + (Gamma_th - 1) rho (eps - eps_c(rho)),  T = (Gamma_th - 1) m_b (eps - eps_c).
// eps below eps_c(rho) is raised to it (rule 8, eps_low = eps(rho, T_min = 0)).
#include <cmath>
#include <cstdint>

#include "EOS/counter.hpp"
#include "EOS/piecewise_polytrope.hpp"
#include "EOS/types.hpp"
#include "EOS/units.hpp"

namespace remnant::eos {

template <class Counter = NoCount>
class Hybrid {
 public:
  static constexpr bool has_temperature = true;
  Hybrid(PiecewisePolytrope cold, double gamma_th, double baryon_mass_MeV = units::neutron_mass_MeV, Bounds b = {})
      : pp_(std::move(cold)), gth_(gamma_th), mb_(baryon_mass_MeV), b_(b) {
    if (!(gamma_th > 1)) throw EosError("hybrid EOS: Gamma_th must be > 1");
    b_.T_min = 0;
    b_.eps_min = pp_.eps(b_.rho_min);
    b_.h_min = b_.rho_min > 0 ? 1 + b_.eps_min + pp_.press(b_.rho_min) / b_.rho_min : 1;
  }
  const PiecewisePolytrope& cold() const { return pp_; }
  double gamma_th() const { return gth_; }
  const Bounds& bounds() const { return b_; }
  bool has_chemical_potentials() const { return false; }
  bool has_composition() const { return false; }
  const Counter& counter() const { return c_; }

  Thermo thermo(double rho, double T, double /*ye*/) const {
    return from_eps_th(rho, std::max(T, 0.0) / ((gth_ - 1) * mb_));
  }
  double press(double rho, double T, double ye) const { return thermo(rho, T, ye).press; }
  double eps(double rho, double T, double) const {
    c_.add();
    return pp_.eps(rho) + std::max(T, 0.0) / ((gth_ - 1) * mb_);
  }

  Inversion temperature(double rho, double eps, double, double = 0, InversionMethod = InversionMethod::exact) const {
    Inversion r;
    const double ec = pp_.eps(rho);
    const double eth_max = b_.T_max / ((gth_ - 1) * mb_);
    r.eps = eps;
    if (!(rho >= b_.rho_min && rho <= b_.rho_max)) r.flags |= kInvRhoClamped;
    if (!(eps > ec)) r.eps = ec, r.flags |= kInvBelowEpsLow;
    else if (eps - ec >= eth_max) r.eps = ec + eth_max, r.flags |= kInvAboveEpsHigh;
    r.T = (gth_ - 1) * mb_ * (r.eps - ec);
    return r;
  }
  Thermo thermo_from_eps(double rho, double eps, double ye, double& T_guess, std::uint32_t* flags = nullptr,
                         InversionMethod = InversionMethod::exact) const {
    const Inversion inv = temperature(rho, eps, ye);
    T_guess = inv.T;
    if (flags) *flags = inv.flags;
    return from_eps_th(rho, inv.eps - pp_.eps(rho));
  }

 private:
  Thermo from_eps_th(double rho, double eth) const {
    c_.add();
    double pc, ec, dpc;
    pp_.eval(rho, pc, ec, dpc);
    Thermo o;
    o.eps = ec + eth;
    o.press = pc + (gth_ - 1) * rho * eth;
    o.h = 1 + o.eps + o.press / rho;
    // cs2 h = dp/drho|_eps + p/rho^2 dp/deps|_rho, with deps_c/drho = p_c/rho^2.
    const double dpdrho = dpc + (gth_ - 1) * eth - (gth_ - 1) * pc / rho;
    const double dpdeps = (gth_ - 1) * rho;
    o.cs2 = (dpdrho + o.press / (rho * rho) * dpdeps) / o.h;
    return o;
  }
  PiecewisePolytrope pp_;
  double gth_, mb_;
  Bounds b_;
  [[no_unique_address]] Counter c_;
};

}  // namespace remnant::eos
