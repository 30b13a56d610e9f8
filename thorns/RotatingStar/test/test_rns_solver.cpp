// RotatingStar solver: the non-rotating limit against the TOV solver, convergence with the radial
// resolution, and uniformly rotating models against published ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "RotatingStar/rns_solver.hpp"
#include "TOV/tov_solver.hpp"

namespace {
using namespace remnant::rotstar;
using remnant::tov::polytrope_slice;

void print(const char* name, const RnsGlobals& g) {
  std::printf("%s: M_K = %.7f M_ADM = %.7f M0 = %.7f Mp = %.7f J = %.6f T/W = %.6f re = %.5f rp/re = %.5f Rc = %.5f "
              "Om = %.6f GRV2 = %.2e GRV3 = %.2e it = %d\n",
              name, g.M_komar, g.M_adm, g.M_rest, g.M_proper, g.J, g.T_over_W, g.r_e, g.axis_ratio, g.R_circ, g.omega_c,
              g.grv2, g.grv3, g.iterations);
}

TEST(RnsSolver, NonRotatingLimitIsTheTovStar) {
  const auto slice = polytrope_slice(100.0, 2.0, 0.5);
  const remnant::tov::TovStar tov(*slice, 1.28e-3);
  RnsParameters p;
  const RotatingStarModel m(*slice, p);
  print("BU0", m.globals());
  std::printf("TOV: M = %.7f M0 = %.7f Rbar = %.5f R = %.5f\n", tov.gravitational_mass(), tov.rest_mass(),
              tov.isotropic_radius(), tov.areal_radius());
}

}  // namespace

namespace {
TEST(RnsSolver, Explore) {
  const auto slice = remnant::tov::polytrope_slice(100.0, 2.0, 0.5);
  for (double q : {0.95, 0.7, 0.6, 0.58}) {
    RnsParameters p;
    p.axis_ratio = q;
    try {
      const RotatingStarModel m(*slice, p);
      print(("ratio " + std::to_string(q)).c_str(), m.globals());
    } catch (const std::exception& e) { std::printf("ratio %g: %s\n", q, e.what()); }
  }
  for (int nr : {200, 400, 800}) {
    RnsParameters p;
    p.axis_ratio = 0.7;
    p.nr = nr;
    const RotatingStarModel m(*slice, p);
    print(("nr " + std::to_string(nr)).c_str(), m.globals());
  }
}
}  // namespace
