#pragma once
// The one conversion between the code's magnetic field and Gauss.
//
// Remnant's B (HydroBase::Bvec, Con2Prim's state) is the Eulerian field in Heaviside-Lorentz units
// with sqrt(4 pi) absorbed, in code units G = c = M_sun = 1: the magnetic pressure is b^2 / 2 and
// the energy density of the field in the Eulerian frame B^2 / 2, both in code pressure units.
// In Gaussian cgs units the same energy density is B_G^2 / (8 pi) erg/cm^3. So
//   B_G^2 / (8 pi) = (B_code^2 / 2) * p_unit,   p_unit = M_sun c^2 / L^3 (erg/cm^3), L = G M_sun / c^2,
//   B_G = sqrt(4 pi p_unit) * B_code = sqrt(4 pi) * c^4 / (G^(3/2) M_sun) * B_code,
// with p_unit = units::pressure_cgs (EOS/units.hpp, IAU 2015 G M_sun and CODATA 2018 G):
//   kGaussPerCodeB = 8.3517e19 G.
#include "EOS/units.hpp"

namespace remnant::hydrobase {

namespace detail {
// sqrt by Newton's iteration, usable in constant expressions (std::sqrt is not constexpr in C++20).
constexpr double constexpr_sqrt(double x) {
  double r = x > 1 ? x : 1.0;
  for (int it = 0; it < 200; ++it) {
    const double next = 0.5 * (r + x / r);
    if (next == r) break;
    r = next;
  }
  return r;
}
inline constexpr double kFourPi = 4.0 * 3.141592653589793238462643383279502884;
}  // namespace detail

// Gauss per code unit of B: B_gauss = kGaussPerCodeB * B_code.
inline constexpr double kGaussPerCodeB = detail::constexpr_sqrt(detail::kFourPi * units::pressure_cgs);

inline constexpr double gauss_from_code(double b_code) { return b_code * kGaussPerCodeB; }
inline constexpr double code_from_gauss(double b_gauss) { return b_gauss / kGaussPerCodeB; }

}  // namespace remnant::hydrobase
