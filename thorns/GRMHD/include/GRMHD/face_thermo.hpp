#pragma once
// Which thermodynamic variables are reconstructed, and the EOS call that completes a face state.
// Ideal gas: the pressure (continuous across contact discontinuities; eps, h, cs2 follow in closed
// form, no EOS inversion). Every other EOS: the temperature and the pressure; one EOS call
// (rho, T, Ye) gives eps and cs2 (no eps -> T inversion at faces), the pressure is the reconstructed
// one. p(rho_face, T, Ye_face) would not do: a table is interpolated linearly in ln rho and Ye, so a
// star's rho(r) and Ye(r) have kinks at the table's nodes while p(r) stays smooth (hydrostatic), and
// the kinked face values put an O(dx) error into p there: an O(1) force in the node's cells that does
// not converge (issue 20: the SFHo star's drift grew with resolution).
// The reconstructed p is kept within a factor kFacePressureBand of p(rho_face, T_face, Ye_face): at a
// kink the two differ by O(dx), far inside the band, but at a stellar surface rho and p are limited
// independently, so the face's p / rho could exceed both cells' by orders of magnitude: that enthalpy
// heated the atmosphere next to the surface to eps ~ 1 and v ~ 0.9 (head-on, issue 18: CFL time step
// 0.51 instead of ~1.7 at dx = 1.5 within 5 steps; 0.8 .. 1.2 with the band, as before issue 20).
#include <algorithm>
#include <type_traits>

#include "EOS/ideal_gas.hpp"
#include "GRMHD/valencia.hpp"

namespace remnant::grmhd {

inline constexpr double kFacePressureBand = 1.1;

template <class E>
struct is_ideal_gas : std::false_type {};
template <class C>
struct is_ideal_gas<eos::IdealGas<C>> : std::true_type {};
template <class E>
inline constexpr bool reconstructs_pressure = is_ideal_gas<E>::value;

// The reconstructed thermal variable of a cell: p or T.
template <class E>
inline double thermal_variable(double press, double temperature) {
  if constexpr (reconstructs_pressure<E>) return press;
  else return temperature;
}

// Fills press, eps, h, cs2 of s from its rho, ye, the reconstructed thermal variable and (not ideal
// gas) the reconstructed pressure. The error policy after reconstruction: T and Ye are clamped into
// the EOS range (rules 4, 6, 7), the pressure into the band around the EOS's.
template <class E>
inline void complete_face_thermo(const E& eos, FluidState& s, double thermal, double press) {
  if constexpr (reconstructs_pressure<E>) {
    (void)press;  // the thermal variable is the pressure
    const double g = eos.gamma();
    const double p = std::max(thermal, 0.0);
    const double p_over_rho = p / s.rho;
    s.press = p;
    s.eps = p_over_rho / (g - 1.0);
    s.h = 1.0 + g * s.eps;
    s.cs2 = g * p_over_rho / s.h;
  } else {
    const auto& b = eos.bounds();
    const double T = std::clamp(thermal, b.T_min, b.T_max);
    s.ye = std::clamp(s.ye, b.ye_min, b.ye_max);
    const auto th = eos.thermo(s.rho, T, s.ye);
    const double p_eos = std::max(th.press, 0.0);
    s.press = std::clamp(press, p_eos / kFacePressureBand, p_eos * kFacePressureBand);
    s.eps = th.eps;
    s.h = 1.0 + th.eps + s.press / s.rho;
    s.cs2 = th.cs2;
  }
}

}  // namespace remnant::grmhd
