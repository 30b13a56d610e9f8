#pragma once
// What a master-function solver hands back to the recovery pipeline (recover.hpp): the fluid state at
// its root, before the atmosphere check, the error policy and the final EOS call.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "Con2Prim/metric.hpp"

namespace remnant::con2prim {

// One master-function evaluation and the state it was computed from (Kastaun: x = mu;
// Palenzuela: x = h W). Brent keeps whole records so that the root's state needs no recomputation.
// T: tables record ln T instead (lnT; T = 0 unless rules 8/9 fixed it at T_min or T_max exactly),
// so that exp runs once, at the root (temperature()).
struct MasterEval {
  double x = 0, f = 0;
  double W = 1, rho0 = 0, eps = 0, T = 0;
  std::uint32_t inv_flags = 0;
  bool has_lnT = false;
  double lnT = 0;
  double temperature() const { return has_lnT && !(T > 0) ? std::exp(lnT) : T; }
  double rel_change(const MasterEval& o) const {
    return std::max(std::abs(o.W - W) / W, std::abs(o.eps - eps) / std::abs(eps));
  }
  static MasterEval lerp(const MasterEval& a, const MasterEval& b, double t) {
    auto mix = [t](double p, double q) { return p + t * (q - p); };
    MasterEval m{mix(a.x, b.x), 0.0, mix(a.W, b.W), mix(a.rho0, b.rho0), mix(a.eps, b.eps), 0.0, a.inv_flags};
    if (a.has_lnT) {
      m.has_lnT = true;
      m.lnT = mix(a.lnT, b.lnT);
      // A clamped end (T_min/T_max exactly): mix T itself, so that T stays inside [T_min, T_max].
      if (a.T > 0 || b.T > 0) m.T = mix(a.temperature(), b.temperature());
    } else {
      m.T = mix(a.T, b.T);
    }
    return m;
  }
};

struct RootSolution {
  double rho = 0;   // D / W, not clamped to the table (rule 1 needs the raw value)
  double W = 1;
  Vec3 v{};         // v^i
  double eps = 0;   // after the eps -> T clamps (rules 8/9)
  double T = 0;
  double lnT = NAN;  // tables: ln T of the root where T = exp(lnT) (not clamped to T_min/T_max)
  std::uint32_t inversion_flags = 0;
  bool bracketed = true;
  bool converged = true;
  bool early_stop = false;  // Brent stopped before closing its bracket (root_finding.hpp)
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
