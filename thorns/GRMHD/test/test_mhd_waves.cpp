// Exact MHD solutions through the whole chain (parfile, Grid, MoL RK3, GRMHD with the field evolved,
// Con2Prim with B): the large-amplitude circularly polarised Alfven wave (src/alfven_wave.hpp) after
// one period converges at second order in L1 of B^2, B^3 and v^2; B^1 stays B0 exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "alfven_wave.hpp"
#include "mhd_run.hpp"
#include "remnant/vars/HydroBase.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;
using namespace remnant::grmhd::test;

struct WaveErrors {
  double field = 0, velocity = 0, bx = 0;
};

// ny > 1: the same wave (along x, uniform in y) on a 2D grid of n x ny cells, periodic in y, so that
// the edge EMFs E_z combine x and y faces (the plane-parallel case of the 2D EMF schemes).
WaveErrors alfven_errors(int n, const std::string& reconstruction, const std::string& emf, const std::string& extra,
                         int ny = 1) {
  AlfvenWave w;  // the defaults of GRMHD::alfven_wave with gamma = 4/3 on [0, 1]
  const double period = 1.0 / w.speed();
  const std::string grid =
      ny == 1 ? "dimension: 1, ncells: [" + std::to_string(n) + ", 1, 1], block_size: [" + std::to_string(n / 4) +
                    ", 1, 1], xmin: [0, 0, 0], xmax: [1, 1, 1], ghost_zones: 3, "
                    "boundary_lower: [periodic, outflow, outflow], boundary_upper: [periodic, outflow, outflow]"
              : "dimension: 2, ncells: [" + std::to_string(n) + ", " + std::to_string(ny) + ", 1], block_size: [" +
                    std::to_string(n / 4) + ", " + std::to_string(ny) +
                    ", 1], xmin: [0, 0, 0], xmax: [1, 1, 1], ghost_zones: 3, "
                    "boundary_lower: [periodic, periodic, outflow], boundary_upper: [periodic, periodic, outflow]";
  char t[64];
  std::snprintf(t, sizeof t, "%.17g", period);
  MhdRun run(mhd_parfile(grid, "reconstruction: " + reconstruction + ", emf: " + emf + ", initial_data: alfven_wave" + extra,
                         std::string("cfl: 0.4, final_time: ") + t, 4.0 / 3.0));
  EXPECT_NEAR(run.sim().context().time(), period, 1e-12);
  using Prim = vars::HydroBase::prim;
  const int prim = run.group(Prim::full_name), bvec = run.group("HydroBase::Bvec"), bx = run.group("HydroBase::Bface1");
  WaveErrors e;
  for (Block* b : run.blocks()) {
    const Prim p(*b, prim);
    for (int j = 0; j < b->n[1]; ++j)
      for (int i = 0; i < b->n[0]; ++i) {
        const double xl = b->face_coordinate(0, i), xr = b->face_coordinate(0, i + 1), dx = b->dx[0] / ny;
        const auto exact = w.field_average(xl, xr, period);
        const auto v = w.velocity(b->x(0, i), period);
        e.field += (std::abs(b->field(bvec, 1)(i, j, 0) - exact[1]) + std::abs(b->field(bvec, 2)(i, j, 0) - exact[2])) * dx;
        e.velocity += std::abs(p.vel(1, i, j, 0) - v[1]) * dx;
        e.bx = std::max(e.bx, std::abs(b->field(bx, 0)(i, j, 0) - w.B0));
      }
  }
  return e;
}

void expect_second_order(const std::string& rec, const std::string& emf, const std::string& extra = "") {
  const WaveErrors a = alfven_errors(32, rec, emf, extra), b = alfven_errors(64, rec, emf, extra),
                   c = alfven_errors(128, rec, emf, extra);
  const double pf1 = std::log2(a.field / b.field), pf2 = std::log2(b.field / c.field);
  const double pv2 = std::log2(b.velocity / c.velocity);
  std::printf("Alfven wave (%s, %s%s): L1(B^2)+L1(B^3) %.3e %.3e %.3e (orders %.2f %.2f), L1(v^2) %.3e %.3e %.3e (order %.2f), max|B^1 - B0| %.1e\n",
              rec.c_str(), emf.c_str(), extra.c_str(), a.field, b.field, c.field, pf1, pf2, a.velocity, b.velocity, c.velocity, pv2,
              std::max({a.bx, b.bx, c.bx}));
  EXPECT_GT(pf2, 1.8);
  EXPECT_GT(pv2, 1.8);
  EXPECT_LT(c.field, 2e-3);
  EXPECT_EQ(std::max({a.bx, b.bx, c.bx}), 0.0);
}

}  // namespace

TEST(AlfvenWave, ConvergesAtSecondOrderMC) { expect_second_order("mc", "uct_hll"); }
TEST(AlfvenWave, ConvergesAtSecondOrderPPMArithmetic) { expect_second_order("ppm", "arithmetic"); }
// uct_contact (Gardiner & Stone 2005) in 2D: for this plane-parallel wave the contact EMF must
// reduce to the 1D upwind flux, so the 2D run reproduces the 1D errors (to round-off) and order.
TEST(AlfvenWave, ContactEmfIn2DReducesToThe1DWave) {
  const std::string rec = "mc";
  WaveErrors e2[3], e1[3];
  const int ns[3] = {32, 64, 128};
  for (int r = 0; r < 3; ++r) {
    e2[r] = alfven_errors(ns[r], rec, "uct_contact", "", 4);
    e1[r] = alfven_errors(ns[r], rec, "uct_hll", "");
  }
  const double order = std::log2(e2[1].field / e2[2].field), vorder = std::log2(e2[1].velocity / e2[2].velocity);
  std::printf("Alfven wave 2D (n x 4, mc, uct_contact): L1(B^2)+L1(B^3) %.3e %.3e %.3e (order %.2f), L1(v^2) order %.2f; "
              "1D uct_hll %.3e %.3e %.3e\n",
              e2[0].field, e2[1].field, e2[2].field, order, vorder, e1[0].field, e1[1].field, e1[2].field);
  EXPECT_GT(order, 1.8);
  EXPECT_GT(vorder, 1.8);
  for (int r = 0; r < 3; ++r) {
    EXPECT_NEAR(e2[r].field, e1[r].field, 1e-9 * e1[r].field) << ns[r];
    EXPECT_EQ(e2[r].bx, 0.0);
  }
}

// Extremum-preserving PPM for the fluid and for the uct_hll edge states (GRMHD::emf_reconstruction),
// in 2D so that the edge EMFs reconstruct the y-face field along x: second order as MC and PPM.
TEST(AlfvenWave, ExtremumPreservingPpmEdgesIn2D) {
  WaveErrors e[3];
  const int ns[3] = {32, 64, 128};
  for (int r = 0; r < 3; ++r) e[r] = alfven_errors(ns[r], "ppm_ep", "uct_hll", ", emf_reconstruction: ppm_ep", 4);
  const double order = std::log2(e[1].field / e[2].field), vorder = std::log2(e[1].velocity / e[2].velocity);
  std::printf("Alfven wave 2D (n x 4, ppm_ep, uct_hll with ppm_ep edges): L1(B^2)+L1(B^3) %.3e %.3e %.3e (order %.2f), "
              "L1(v^2) order %.2f\n",
              e[0].field, e[1].field, e[2].field, order, vorder);
  EXPECT_GT(order, 1.8);
  EXPECT_GT(vorder, 1.8);
  EXPECT_LT(e[2].field, 2e-3);
  for (const WaveErrors& w : e) EXPECT_EQ(w.bx, 0.0);
}

// The positivity limiter leaves a smooth wave alone (the same errors as without it).
TEST(AlfvenWave, ConvergesAtSecondOrderMCWithPositivityLimiter) {
  expect_second_order("mc", "uct_hll", ", positivity_limiter: lax_friedrichs");
}
