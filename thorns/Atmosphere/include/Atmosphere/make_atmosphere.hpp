#pragma once
// The atmosphere state at start-up. Analytic EOS: the paper's polytropic values
//   p = K rho^Gamma, eps = K rho^(Gamma-1) / (Gamma-1), cs2 = p Gamma (Gamma-1) / (rho (Gamma-1) + p Gamma),
// with T from the EOS's own eps -> T (0 for a cold polytrope). Tabulated EOS: T_atm = T_min and Ye_atm
// from neutrinoless beta equilibrium at (rho_atm, T_min); eps, p, cs2 from the table there.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "Atmosphere/atmosphere.hpp"
#include "EOS/beta_equilibrium.hpp"
#include "EOS/eos.hpp"

namespace remnant::atmosphere {

struct AtmosphereConfig {
  double rho_thr = 1e-14;  // code units
  double xi = 0.9;         // rho_atm / rho_thr
  double poly_K = 100.0;   // analytic EOS only
  double poly_gamma = 2.0;
  double ye_analytic = 0.5;
  double sigma_max = 1000;  // b^2/rho cap in atmosphere cells
};

inline void check(const AtmosphereConfig& c) {
  if (!(c.rho_thr > 0)) throw std::invalid_argument("atmosphere: rho_thr must be > 0");
  if (!(c.xi > 0 && c.xi <= 1)) throw std::invalid_argument("atmosphere: xi must be in (0, 1]");
  if (!(c.poly_K > 0 && c.poly_gamma > 1)) throw std::invalid_argument("atmosphere: need K > 0 and Gamma > 1");
  if (!(c.sigma_max > 0)) throw std::invalid_argument("atmosphere: sigma_max must be > 0");
}

template <class E>
Atmosphere polytropic_atmosphere(const E& eos, const AtmosphereConfig& c) {
  check(c);
  Atmosphere a;
  a.rho_thr = c.rho_thr;
  a.rho = c.xi * c.rho_thr;
  const double G = c.poly_gamma;
  a.press = c.poly_K * std::pow(a.rho, G);
  a.eps = c.poly_K * std::pow(a.rho, G - 1) / (G - 1);
  a.cs2 = a.press * G * (G - 1) / (a.rho * (G - 1) + a.press * G);
  a.ye = c.ye_analytic;
  a.ye_source = YeSource::parameter;
  a.T = eos.temperature(a.rho, a.eps, a.ye).T;
  return a;
}

template <class C>
Atmosphere tabulated_atmosphere(const eos::Tabulated<C>& eos, const AtmosphereConfig& c) {
  check(c);
  const eos::Bounds& b = eos.bounds();
  Atmosphere a;
  a.rho_thr = c.rho_thr;
  a.rho = c.xi * c.rho_thr;
  a.T = b.T_min;
  if (eos.has_chemical_potentials()) {
    const eos::BetaEquilibrium be = eos::beta_equilibrium_ye(eos, a.rho, a.T);
    a.ye = be.ye;
    a.ye_source = be.bracketed ? YeSource::beta_equilibrium : YeSource::beta_nearest_end;
  } else {
    a.ye = std::clamp(c.ye_analytic, b.ye_min, b.ye_max);
    a.ye_source = YeSource::table_without_mu;
  }
  const eos::Thermo th = eos.thermo(a.rho, a.T, a.ye);
  a.eps = th.eps;
  a.press = th.press;
  a.cs2 = th.cs2;
  return a;
}

template <class E>
Atmosphere make_atmosphere(const E& eos, const AtmosphereConfig& c) {
  Atmosphere a;
  if constexpr (requires { eos.table(); }) a = tabulated_atmosphere(eos, c);
  else a = polytropic_atmosphere(eos, c);
  a.sigma_max = c.sigma_max;
  return a;
}

// For the shared EOS handle (dispatches once).
Atmosphere make_atmosphere(const eos::EOS& eos, const AtmosphereConfig& c);

std::string describe(const Atmosphere& a);

}  // namespace remnant::atmosphere
