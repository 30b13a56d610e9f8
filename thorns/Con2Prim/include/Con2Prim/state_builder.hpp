#pragma once
// A primitive state from (rho, T, Ye), a Lorentz factor W and a magnetisation b^2/(2p), with given
// directions of v and B: the states of the paper's benchmark planes and of the round-trip tests.
#include <cmath>

#include "Con2Prim/metric.hpp"
#include "Con2Prim/state.hpp"
#include "EOS/types.hpp"

namespace remnant::con2prim {

template <class E>
Primitives make_state(const E& eos, const Metric3& g, double rho, double T, double ye, double W,
                      double b2_over_2p, const Vec3& v_dir, const Vec3& B_dir) {
  Primitives p;
  p.rho = rho;
  p.T = T;
  p.ye = ye;
  p.W = W;
  const eos::Thermo th = eos.thermo(rho, T, ye);
  p.eps = th.eps;
  p.press = th.press;
  p.cs2 = th.cs2;
  const double speed = std::sqrt((W - 1) * (W + 1)) / W;
  const double vn = std::sqrt(g.norm2_up(v_dir));
  for (int i = 0; i < 3; ++i) p.v[i] = speed * v_dir[i] / vn;
  // b^2 = B^2/W^2 + (B.v)^2 = beta^2 [n^2/W^2 + (n.v)^2] for B = beta n.
  const double n2 = g.norm2_up(B_dir), nv = dot(g.lower(B_dir), p.v);
  const double b2 = 2 * p.press * b2_over_2p;
  const double beta = b2 > 0 ? std::sqrt(b2 / (n2 / (W * W) + nv * nv)) : 0.0;
  for (int i = 0; i < 3; ++i) p.B[i] = beta * B_dir[i];
  return p;
}

}  // namespace remnant::con2prim
