// A magnetised Riemann problem with an exact solution: with B^1 = 0, v along x^1 and a transverse
// field, ideal RMHD of a Gamma = 2 gas is exactly the SRHD of a Gamma = 2 gas in (rho, p_tot, v),
// p_tot = p + b^2/2: the momentum and energy fluxes only see rho h + b^2 = rho + 2 p_tot and p_tot,
// and the fast speed a^2 = cs^2 + va^2 - cs^2 va^2 is that gas's sound speed. So the exact SRHD
// solver (exact_riemann_srhd.hpp) gives the plateaus of the magnetised problem: compared to 1 %
// (a Balsara-1-like tube without the normal field: rho 1 / 0.125, p 1 / 0.1, B^2 1 / 0.5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "exact_riemann_srhd.hpp"
#include "mhd_run.hpp"
#include "remnant/vars/HydroBase.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;
using namespace remnant::grmhd::test;

struct Plateau {
  const char* name;
  double lo, hi;  // xi range where the exact solution is constant
  double exact;
};

TEST(MHDRiemann, TransverseFieldTubeMatchesTheExactPlateaus) {
  const double t = 0.4, x0 = 0.5;
  const SrhdState left{1.0, 0.0, 1.0 + 0.5 * 1.0}, right{0.125, 0.0, 0.1 + 0.5 * 0.25};
  const ExactRiemannSRHD exact(2.0, left, right);
  const std::string grid = "dimension: 1, ncells: [800, 1, 1], block_size: [100, 1, 1], xmin: [0, 0, 0], xmax: [1, 1, 1], "
                           "ghost_zones: 3, boundary_lower: [outflow, outflow, outflow], boundary_upper: [outflow, outflow, outflow]";
  MhdRun run(mhd_parfile(grid,
                         "reconstruction: mc, initial_data: shock_tube, shock_position: 0.5, "
                         "shock_left: [1.0, 0.0, 0.0, 0.0, 1.0], shock_right: [0.125, 0.0, 0.0, 0.0, 0.1], "
                         "shock_field_left: [0.0, 1.0, 0.0], shock_field_right: [0.0, 0.5, 0.0]",
                         "cfl: 0.4, final_time: 0.4", 2.0));
  // The exact plateaus: constant runs of the sampled solution.
  const double vs = exact.star_velocity(), ps = exact.star_pressure();
  auto rho_at = [&](double xi) { return exact.sample(xi).rho; };
  const double rho_l = rho_at(vs - 1e-9), rho_r = rho_at(vs + 1e-9);
  double tail = vs, front = vs;
  while (std::abs(rho_at(tail - 1e-3) - rho_l) < 1e-12 * rho_l) tail -= 1e-3;
  while (std::abs(rho_at(front + 1e-3) - rho_r) < 1e-12 * rho_r) front += 1e-3;
  // Sample the central half of each plateau.
  auto centre = [](double a, double b) { return std::pair{a + 0.25 * (b - a), b - 0.25 * (b - a)}; };
  const auto [l0, l1] = centre(tail, vs);
  const auto [r0, r1] = centre(vs, front);
  using Prim = vars::HydroBase::prim;
  const int prim = run.group(Prim::full_name), bvec = run.group("HydroBase::Bvec");
  double sum[5] = {0, 0, 0, 0, 0};  // rho_l, rho_r, p_tot, v, B^2 / rho on the right
  int cnt[5] = {0, 0, 0, 0, 0};
  for (Block* b : run.blocks()) {
    const Prim p(*b, prim);
    for (int i = 0; i < b->n[0]; ++i) {
      const double xi = (b->x(0, i) - x0) / t;
      const double W = p.W(i, 0, 0), By = b->field(bvec, 1)(i, 0, 0);
      const double ptot = p.press(i, 0, 0) + 0.5 * By * By / (W * W);
      auto add = [&](int q, double v) { sum[q] += v, ++cnt[q]; };
      if (xi > l0 && xi < l1) add(0, p.rho(i, 0, 0)), add(2, ptot), add(3, p.vel(0, i, 0, 0));
      if (xi > r0 && xi < r1) add(1, p.rho(i, 0, 0)), add(2, ptot), add(3, p.vel(0, i, 0, 0)), add(4, By / (p.rho(i, 0, 0) * W));
    }
  }
  const Plateau plateaus[5] = {{"rho*_L", l0, l1, rho_l}, {"rho*_R", r0, r1, rho_r}, {"p_tot*", l0, r1, ps},
                               {"v*", l0, r1, vs}, {"B^2/(rho W) right", r0, r1, 0.5 / 0.125}};
  for (int q = 0; q < 5; ++q) {
    ASSERT_GT(cnt[q], 5) << plateaus[q].name;
    const double num = sum[q] / cnt[q], rel = std::abs(num / plateaus[q].exact - 1);
    std::printf("%-18s exact %.6f numerical %.6f (%d cells) relative error %.2e\n", plateaus[q].name, plateaus[q].exact, num,
                cnt[q], rel);
    EXPECT_LT(rel, 0.01) << plateaus[q].name;
  }
}

}  // namespace
