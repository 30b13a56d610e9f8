#pragma once
// Conserved from primitive variables (state.hpp gives the definitions), and b^2 in the fluid frame.
#include "Con2Prim/metric.hpp"
#include "Con2Prim/state.hpp"

namespace remnant::con2prim {

inline Conserved prim_to_cons(const Primitives& p, const Metric3& g) {
  const Vec3 v_low = g.lower(p.v);
  const Vec3 B_low = g.lower(p.B);
  const double v2 = dot(v_low, p.v), B2 = dot(B_low, p.B), Bv = dot(B_low, p.v);
  const double z = (p.rho * (1 + p.eps) + p.press) * p.W * p.W;  // rho h W^2
  Conserved c;
  c.D = p.rho * p.W;
  for (int i = 0; i < 3; ++i) c.S[i] = (z + B2) * v_low[i] - Bv * B_low[i];
  c.tau = z - p.press + 0.5 * B2 * (1 + v2) - 0.5 * Bv * Bv - c.D;
  c.B = p.B;
  c.DYe = c.D * p.ye;
  return c;
}

// b^2 = b^mu b_mu = B^2 / W^2 + (B.v)^2.
inline double b_squared(const Primitives& p, const Metric3& g) {
  const Vec3 B_low = g.lower(p.B);
  const double Bv = dot(B_low, p.v);
  return dot(B_low, p.B) / (p.W * p.W) + Bv * Bv;
}

}  // namespace remnant::con2prim
