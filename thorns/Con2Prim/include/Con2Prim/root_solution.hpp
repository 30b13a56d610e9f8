#pragma once
// What a master-function solver hands back to the recovery pipeline (recover.hpp): the fluid state at
// its root, before the atmosphere check, the error policy and the final EOS call.
#include <cmath>
#include <cstdint>

#include "Con2Prim/metric.hpp"

namespace remnant::con2prim {

struct RootSolution {
  double rho = 0;   // D / W, not clamped to the table (rule 1 needs the raw value)
  double W = 1;
  Vec3 v{};         // v^i
  double eps = 0;   // after the eps -> T clamps (rules 8/9)
  double T = 0;
  std::uint32_t inversion_flags = 0;
  bool bracketed = true;
  bool converged = true;
  int iterations = 0, evaluations = 0, aux_iterations = 0;
};

// v^i rescaled so that gamma_ij v^i v^j = 1 - 1/W^2 (the root's W), keeping its direction.
inline void match_speed_to_W(const Metric3& g, double W, Vec3& v) {
  const double target = (W - 1) * (W + 1) / (W * W);
  const double now = g.norm2_up(v);
  if (now > 0) {
    const double s = std::sqrt(target / now);
    for (double& vi : v) vi *= s;
  }
}

}  // namespace remnant::con2prim
