#pragma once
// The large-amplitude circularly polarised Alfven wave, an exact nonlinear solution of ideal SRMHD
// (Komissarov 1997; Del Zanna et al. 2003, 2007), along x^1 in flat space:
//   B = B0 (1, eta cos k(x - vA t), eta sin k(x - vA t)),  v = -vA (0, B^2, B^3) / B0,  rho, p uniform,
//   vA^2 = B0^2 / (rho h + B0^2 (1 + eta^2)) / [ (1 + sqrt(1 - (2 eta B0^2 / (rho h + B0^2 (1 + eta^2)))^2)) / 2 ],
// k = 2 pi / L with L the domain length along x^1 (periodic). An ideal gas gives h.
#include <array>

#include "remnant/context.hpp"

namespace remnant::grmhd {

struct AlfvenWave {
  double rho = 1, press = 0.1, B0 = 1, eta = 1, gamma = 4.0 / 3.0, length = 1, x0 = 0;
  double speed() const;  // vA
  // B^i and v^i at x^1 = x and time t.
  std::array<double, 3> field(double x, double t) const;
  std::array<double, 3> velocity(double x, double t) const;
  // The average of B^2, B^3 over [xl, xr] at time t (exact, for face values and errors).
  std::array<double, 3> field_average(double xl, double xr, double t) const;
};

AlfvenWave alfven_wave_from(const Context& ctx);

// GRMHD_AlfvenWave (primitives) and the face fields of the wave (called by GRMHD_InitialField).
void alfven_wave_initial_data(Context& ctx);
void alfven_wave_field(Context& ctx);

}  // namespace remnant::grmhd
