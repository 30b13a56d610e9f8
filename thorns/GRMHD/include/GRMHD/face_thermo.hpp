#pragma once
// Which thermodynamic variable is reconstructed, and the EOS call that completes a face state.
// Ideal gas: the pressure (continuous across contact discontinuities; eps, h, cs2 follow in closed
// form, no EOS inversion). Every other EOS: the temperature, then one EOS call (rho, T, Ye) — no
// eps -> T inversion at faces.
#include <algorithm>
#include <type_traits>

#include "EOS/ideal_gas.hpp"
#include "GRMHD/valencia.hpp"

namespace remnant::grmhd {

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

// Fills press, eps, h, cs2 of s from its rho, ye and the reconstructed thermal variable. The
// error policy after reconstruction: T and Ye are clamped into the EOS range (rules 4, 6, 7), a
// negative pressure becomes zero.
template <class E>
inline void complete_face_thermo(const E& eos, FluidState& s, double thermal) {
  if constexpr (reconstructs_pressure<E>) {
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
    s.press = th.press;
    s.eps = th.eps;
    s.h = th.h;
    s.cs2 = th.cs2;
  }
}

}  // namespace remnant::grmhd
