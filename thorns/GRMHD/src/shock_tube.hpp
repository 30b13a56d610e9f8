#pragma once
// Riemann-problem initial data along x^0 (Marti & Mueller shock tubes): left state for x < x0,
// right state otherwise, written as primitives; an ideal-gas EOS gives eps = p / ((Gamma-1) rho).
#include <array>

#include "remnant/context.hpp"

namespace remnant::grmhd {

struct ShockTubeState {
  double rho = 1, press = 1;
  std::array<double, 3> v{0, 0, 0};
};

void shock_tube_initial_data(Context& ctx);

}  // namespace remnant::grmhd
