#pragma once
// Neutrinoless beta equilibrium mu_e + mu_p - mu_n = 0: Ye(rho) at fixed T by Brent on
// [Ye_min, Ye_max] (paper, atmosphere), and a cold beta-equilibrium slice for initial data.
#include <cmath>
#include <vector>

#include "EOS/brent.hpp"
#include "EOS/errors.hpp"
#include "EOS/tabulated.hpp"

namespace remnant::eos {

struct BetaEquilibrium {
  double ye = 0;
  bool bracketed = true;  // false: no sign change in [Ye_min, Ye_max], ye is the nearer end
  int iterations = 0;
};

template <class C>
BetaEquilibrium beta_equilibrium_ye(const Tabulated<C>& eos, double rho, double T, double ye_tol = 1e-12) {
  if (!eos.has_chemical_potentials())
    throw EosError(eos.table().file + ": no chemical potentials, cannot find beta equilibrium");
  const Bounds& b = eos.bounds();
  auto f = [&](double ye) { return eos.mu_nu(rho, T, ye); };
  const double flo = f(b.ye_min), fhi = f(b.ye_max);
  BetaEquilibrium r;
  if ((flo > 0) == (fhi > 0)) {
    r.bracketed = false;
    r.ye = std::abs(flo) < std::abs(fhi) ? b.ye_min : b.ye_max;
    return r;
  }
  const BrentResult br = brent(f, b.ye_min, b.ye_max, flo, fhi, ye_tol, 100);
  r.ye = br.x;
  r.iterations = br.iterations;
  return r;
}

// One row per density: the cold (T = T_slice) beta-equilibrium state, e.g. for TOV initial data.
struct BetaSlice {
  double T = 0;
  std::vector<double> rho, ye, press, eps, cs2;
  std::vector<bool> bracketed;
};

template <class C>
BetaSlice beta_equilibrium_slice(const Tabulated<C>& eos, double T, const std::vector<double>& rhos) {
  BetaSlice s;
  s.T = T;
  for (double rho : rhos) {
    const BetaEquilibrium be = beta_equilibrium_ye(eos, rho, T);
    const Thermo th = eos.thermo(rho, T, be.ye);
    s.rho.push_back(rho);
    s.ye.push_back(be.ye);
    s.press.push_back(th.press);
    s.eps.push_back(th.eps);
    s.cs2.push_back(th.cs2);
    s.bracketed.push_back(be.bracketed);
  }
  return s;
}

// The slice at the table's density nodes and T_min.
template <class C>
BetaSlice cold_beta_slice(const Tabulated<C>& eos) {
  std::vector<double> rhos;
  const Axis& a = eos.table().lrho;
  for (int i = 0; i < a.n; ++i) rhos.push_back(std::exp(a.node(i)));
  rhos.front() = eos.bounds().rho_min;  // exp(log(x)) may round outside the table
  rhos.back() = eos.bounds().rho_max;
  return beta_equilibrium_slice(eos, eos.bounds().T_min, rhos);
}

}  // namespace remnant::eos
