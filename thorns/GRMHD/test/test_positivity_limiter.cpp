// The positivity limiter of the rest-mass fluxes (src/positivity_limiter.hpp): a line of cells with
// a near-empty cell that anti-diffusive high-order fluxes drain below zero in one forward-Euler
// step; the limited fluxes keep D >= epsilon there, leave faces that need no limiting bit for bit,
// keep D Ye / D = Ye, and give the face shared by two blocks the same value on both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "groups.hpp"
#include "mhd_run.hpp"
#include "positivity_limiter.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;
using namespace remnant::grmhd::test;

constexpr double kDt = 0.2 / 32.0;  // dt / dx = 0.2 on 32 cells of [0, 1]: within 1/(2N) = 0.5
constexpr double kEpsilon = 1e-12;
constexpr double kYe = 0.3;

// A rarefaction around the near-vacuum cell 15 (centre xc), the last of the first block: its upper
// face is the one the two blocks share. Global profiles, so that each block's ghosts agree with
// its neighbour's interior.
constexpr double kDip = 15.5 / 32.0;
double density(double x) { return std::abs(x - kDip) < 1.0 / 64.0 ? 1e-6 : 1.0; }
double velocity(double x) { return 0.5 * std::tanh((x - kDip) * 16.0); }
// A plain upwind-like flux plus an anti-diffusive part that pulls mass out of the dip through its
// two faces (what an overshooting high-order reconstruction does): -/+ 0.5.
double high_order_flux(double xf) {
  const double dist = xf - kDip;
  return velocity(xf) + (std::abs(dist) < 0.02 ? (dist > 0 ? 0.5 : -0.5) : 0.0);
}

struct Line {
  MhdRun run;
  Groups g;
  Line()
      : run(mhd_parfile("dimension: 1, ncells: [32, 1, 1], block_size: [16, 1, 1], xmin: [0, 0, 0], xmax: [1, 1, 1], "
                        "ghost_zones: 3, boundary_lower: [outflow, outflow, outflow], boundary_upper: [outflow, outflow, outflow]",
                        "reconstruction: mc", "max_iterations: 0")) {
    g.prim = run.group("HydroBase::prim");
    g.metric = run.group("Spacetime::metric");
    g.flux = {run.group("GRMHD::flux_x"), run.group("GRMHD::flux_y"), run.group("GRMHD::flux_z")};
    for (Block* b : run.blocks()) {
      for (int i = -b->ng[0]; i < b->n[0] + b->ng[0]; ++i) {
        const double x = b->x(0, i), v = velocity(x);
        b->field(g.prim, Prim::idx::rho)(i, 0, 0) = density(x);
        b->field(g.prim, Prim::idx::vel)(i, 0, 0) = v;
        b->field(g.prim, Prim::idx::W)(i, 0, 0) = 1.0 / std::sqrt(1.0 - v * v);
        b->field(g.prim, Prim::idx::Ye)(i, 0, 0) = kYe;
        b->field(g.metric, Metric::idx::psi)(i, 0, 0) = 1.0;
        b->field(g.metric, Metric::idx::alpha)(i, 0, 0) = 1.0;
        b->field(g.metric, Metric::idx::beta)(i, 0, 0) = 0.0;
      }
      for (int f = 0; f <= b->n[0]; ++f) {
        const double xf = b->face_coordinate(0, f);
        const double fd = high_order_flux(xf);
        b->field(g.flux[0], kD)(f, 0, 0) = fd;
        b->field(g.flux[0], kDYe)(f, 0, 0) = kYe * fd;
      }
    }
  }
  // min over interior cells of D + dt * (flux divergence) with the block's current fluxes.
  double min_updated_density() {
    double m = 1e300;
    for (Block* b : run.blocks()) {
      const Field fd = b->field(g.flux[0], kD), rho = b->field(g.prim, Prim::idx::rho), w = b->field(g.prim, Prim::idx::W);
      for (int i = 0; i < b->n[0]; ++i)
        m = std::min(m, rho(i, 0, 0) * w(i, 0, 0) - kDt / b->dx[0] * (fd(i + 1, 0, 0) - fd(i, 0, 0)));
    }
    return m;
  }
};

TEST(GRMHDPositivityLimiter, KeepsTheDrainedCellAboveEpsilonWhereTheUnlimitedUpdateIsNegative) {
  Line line;
  const double before = line.min_updated_density();
  std::vector<std::vector<double>> unlimited;
  for (Block* b : line.run.blocks())
    unlimited.emplace_back(b->data(line.g.flux[0]), b->data(line.g.flux[0]) + b->size(line.g.flux[0]));
  long limited = 0;
  for (Block* b : line.run.blocks()) limited += limit_block_mass_fluxes(line.g, kDt, kEpsilon, *b);
  const double after = line.min_updated_density();
  std::printf("min D after one Euler step: unlimited %.3e, limited %.3e (%ld faces limited)\n", before, after, limited);
  EXPECT_LT(before, -0.01);
  EXPECT_GE(after, kEpsilon * (1 - 1e-9));
  EXPECT_GT(limited, 0);
  EXPECT_LE(limited, 4);  // the two faces of the dip, seen from both blocks' sides at most
  // Faces away from the dip keep their bits; D Ye follows D with the same theta.
  std::size_t bi = 0;
  for (Block* b : line.run.blocks()) {
    const Field fd = b->field(line.g.flux[0], kD), fy = b->field(line.g.flux[0], kDYe);
    const Field old{unlimited[bi].data() + (fd.origin - b->data(line.g.flux[0])), fd.sj, fd.sk};
    for (int f = 0; f <= b->n[0]; ++f) {
      if (std::abs(b->face_coordinate(0, f) - kDip) > 0.02) EXPECT_EQ(fd(f, 0, 0), old(f, 0, 0)) << f;
      EXPECT_NEAR(fy(f, 0, 0), kYe * fd(f, 0, 0), 1e-15 * (1 + std::abs(fd(f, 0, 0))));
    }
    ++bi;
  }
}

TEST(GRMHDPositivityLimiter, BlocksSharingTheLimitedFaceAgree) {
  // The dip's upper face is the face shared by the two blocks of 16 cells: both limit it alike.
  Line line;
  for (Block* b : line.run.blocks()) limit_block_mass_fluxes(line.g, kDt, kEpsilon, *b);
  auto blocks = line.run.blocks();
  ASSERT_EQ(blocks.size(), 2u);
  Block* lo = blocks[0]->lo[0] < blocks[1]->lo[0] ? blocks[0] : blocks[1];
  Block* hi = lo == blocks[0] ? blocks[1] : blocks[0];
  const double f_lo = lo->field(line.g.flux[0], kD)(lo->n[0], 0, 0), f_hi = hi->field(line.g.flux[0], kD)(0, 0, 0);
  EXPECT_EQ(f_lo, f_hi);
}

TEST(GRMHDPositivityLimiter, ThetaIsOneWhereTheHighOrderTermStaysAboveTheFloor) {
  EXPECT_EQ(positivity_theta(1.0, 1.0, 0.4, 0.4, 0.3, 0.1, 1e-12), 1.0);
  // Cell m would drop to 1 - 0.4 * 3 < 0: theta brings it to the floor exactly.
  const double t = positivity_theta(1.0, 1.0, 0.4, 0.4, 3.0, 0.5, 1e-12);
  EXPECT_NEAR(1.0 - 0.4 * (t * 3.0 + (1 - t) * 0.5), 1e-12, 1e-15);
  // Even the low-order term below the floor: the first-order flux.
  EXPECT_EQ(positivity_theta(1.0, 1.0, 0.4, 0.4, 3.0, 2.6, 1e-12), 0.0);
}

}  // namespace
