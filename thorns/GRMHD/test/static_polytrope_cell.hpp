#pragma once
// A fluid cell at rest on the polytrope p = K rho^Gamma of an ideal gas (Gamma-law EOS), every
// primitive set consistently: the static equilibria of the well-balanced and axis tests.
#include <cmath>

#include "EOS/ideal_gas.hpp"
#include "groups.hpp"
#include "remnant/grid.hpp"

namespace remnant::grmhd::test {

inline void set_static_polytrope_cell(Field* prim, int i, int j, int k, double rho, double K, double gamma,
                                      const eos::IdealGas<>& gas) {
  const double p = K * std::pow(rho, gamma), eps = p / ((gamma - 1.0) * rho);
  prim[Prim::idx::rho](i, j, k) = rho;
  for (int c = 0; c < 3; ++c) prim[Prim::idx::vel + c](i, j, k) = 0.0;
  prim[Prim::idx::eps](i, j, k) = eps;
  prim[Prim::idx::press](i, j, k) = p;
  prim[Prim::idx::temperature](i, j, k) = gas.temperature(rho, eps, 0.5).T;
  prim[Prim::idx::Ye](i, j, k) = 0.5;
  prim[Prim::idx::W](i, j, k) = 1.0;
  prim[Prim::idx::cs2](i, j, k) = gamma * p / (rho + gamma / (gamma - 1.0) * p);
}

}  // namespace remnant::grmhd::test
