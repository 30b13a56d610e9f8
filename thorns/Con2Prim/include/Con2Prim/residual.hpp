#pragma once
// How well a primitive state reproduces the conserved variables it was recovered from: the
// acceptance test that turns a wrong root (an acausal or non-monotonic table can give the master
// function several) into Status::inaccurate instead of a silent "ok".
//
//   residual = max(|D' - D| / D, |tau' - tau| / E, |S' - S| / E),  E = tau + D (> |S| for physical states)
//
// E is the total energy density: the scale on which tau and S are known in double precision, so a
// correct recovery scores at the level of the root tolerance or round-off whatever W and b^2/2p are,
// while an eps wrong by delta_eps scores about delta_eps / h.
#include <algorithm>
#include <cmath>

#include "Con2Prim/metric.hpp"
#include "Con2Prim/state.hpp"

namespace remnant::con2prim {

inline double conserved_residual(const Conserved& got, const Conserved& want, const Metric3& g) {
  const double E = want.tau + want.D;
  const double scale = E > 0 ? E : want.D;
  const Vec3 dS{got.S[0] - want.S[0], got.S[1] - want.S[1], got.S[2] - want.S[2]};
  const double r_D = std::abs(got.D - want.D) / want.D;
  const double r_tau = std::abs(got.tau - want.tau) / scale;
  const double r_S = std::sqrt(std::max(0.0, g.norm2_down(dS))) / scale;
  const double r = std::max({r_D, r_tau, r_S});
  return std::isnan(r) ? INFINITY : r;
}

}  // namespace remnant::con2prim
