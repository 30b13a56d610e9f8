#pragma once
// Test helpers: shared tables, random magnetised states over a table, relative errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "remnant_test/shared_tables.hpp"
#include "Con2Prim/metric.hpp"
#include "Con2Prim/prim_to_cons.hpp"
#include "Con2Prim/state.hpp"
#include "EOS/types.hpp"

namespace c2p_test {

using remnant::test::shared_eos;

inline double rel_err(double got, double want) {
  return want != 0 ? std::abs(got - want) / std::abs(want) : std::abs(got);
}
inline double vec_rel_err(const remnant::con2prim::Vec3& got, const remnant::con2prim::Vec3& want) {
  double d = 0, n = 0;
  for (int i = 0; i < 3; ++i) d += (got[i] - want[i]) * (got[i] - want[i]), n += want[i] * want[i];
  return n > 0 ? std::sqrt(d / n) : std::sqrt(d);
}

// The absolute accuracy of eps that double-precision conserved variables carry: tau and S are of
// order W^2 (rho h + b^2) and cancel down to rho eps, so eps is known to ~1e-16 W^2 (h + b^2/rho) at
// best, whatever the method (ten times that here). Matters only where |eps| is tiny (eps crossing 0).
inline double eps_floor(const remnant::con2prim::Primitives& p, const remnant::con2prim::Metric3& g) {
  const double h = 1 + p.eps + p.press / p.rho;
  return 1e-15 * p.W * p.W * (std::abs(h) + remnant::con2prim::b_squared(p, g) / p.rho);
}
// |got - want| in units of (tol |want| + floor): <= 1 passes.
inline double eps_err(double got, double want, double tol, double floor) {
  return std::abs(got - want) / (tol * std::abs(want) + floor);
}

// A random metric near flat (a perturbed, still positive-definite gamma_ij) and random unit directions.
struct Randomiser {
  std::mt19937_64 rng;
  explicit Randomiser(unsigned seed) : rng(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  remnant::con2prim::Vec3 direction() {
    std::normal_distribution<double> n;
    remnant::con2prim::Vec3 d{n(rng), n(rng), n(rng)};
    const double s = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& x : d) x /= s;
    return d;
  }
  remnant::con2prim::Metric3 metric() {
    const double psi4 = uniform(1.0, 3.0);  // conformal factor^4 of a compact star's interior
    return remnant::con2prim::Metric3::from_lower(psi4 * uniform(0.9, 1.1), psi4 * uniform(-0.1, 0.1),
                                                  psi4 * uniform(-0.1, 0.1), psi4 * uniform(0.9, 1.1),
                                                  psi4 * uniform(-0.1, 0.1), psi4 * uniform(0.9, 1.1));
  }
};

}  // namespace c2p_test
