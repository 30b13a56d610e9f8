#pragma once
// The atmosphere (paper, "Atmosphere treatment"): a cell with rho < rho_thr is atmosphere and gets
//   rho = rho_atm = xi rho_thr, v^i = 0, W = 1, eps = eps_atm, Ye = Ye_atm, p = p_atm, T = T_atm,
//   cs2 = cs2_atm, and keeps its B (with v = 0 the induction equation leaves it alone). Where that B
//   would make the atmosphere's magnetisation b^2/rho exceed sigma_max, rho is raised to b^2/sigma_max
//   (limit_magnetisation; the caller completes p, eps, cs2 from the EOS and the conserved variables),
//   so that a strongly magnetised, nearly empty cell stays recoverable (BHAC and GRHydro cap b^2/rho alike).
// The values are fixed once at start-up (make_atmosphere.hpp); these functions are per cell.
#include <cstdint>

namespace remnant::atmosphere {

// Where Ye_atm came from.
enum class YeSource : std::uint8_t {
  parameter,         // analytic EOS: Atmosphere::ye_analytic
  beta_equilibrium,  // tabulated: root of mu_e + mu_p - mu_n at (rho_atm, T_min)
  beta_nearest_end,  // tabulated: no root in [Ye_min, Ye_max], the end nearer to one
  table_without_mu,  // tabulated without chemical potentials: the parameter, clamped to the table
};

struct Atmosphere {
  double rho_thr = 1e-14;  // code units
  double rho = 0.9e-14;    // rho_atm = xi rho_thr
  double eps = 0, press = 0, T = 0, ye = 0.5, cs2 = 0;
  YeSource ye_source = YeSource::parameter;
  double sigma_max = 1000;  // cap on b^2/rho in atmosphere cells (magnetic fields only)

  // rho (or D in con2prim step (i)) below the threshold; NaN counts as atmosphere.
  bool is_atmosphere(double rho_or_D) const { return !(rho_or_D >= rho_thr); }

  // Sets the atmosphere state on any primitive struct with these members; B is left alone.
  template <class Prim>
  void set(Prim& p) const {
    p.rho = rho;
    p.v[0] = p.v[1] = p.v[2] = 0;
    p.W = 1;
    p.eps = eps;
    p.press = press;
    p.T = T;
    p.ye = ye;
    p.cs2 = cs2;
  }

  // An atmosphere cell (set() applied) threaded by a field with b^2 (= B^i B_i at rest): rho becomes
  // b^2 / sigma_max where that exceeds rho_atm. Returns whether rho changed.
  template <class Prim>
  bool limit_magnetisation(Prim& p, double b2) const {
    if (!(b2 > sigma_max * p.rho)) return false;
    p.rho = b2 / sigma_max;
    return true;
  }
};

}  // namespace remnant::atmosphere
