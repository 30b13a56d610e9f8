// Special-relativistic shock tubes (Marti & Mueller problems 1 and 2) through the whole chain
// (parfile, Grid, MoL RK3, GRMHD with PPM + HLL, Con2Prim) against the exact Riemann solution:
// the L1 error of the density converges at about first order (discontinuous solution).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "remnant/vars/HydroBase.hpp"
#include "exact_riemann_srhd.hpp"
#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace {

using namespace remnant;
using grmhd::test::ExactRiemannSRHD;
using grmhd::test::SrhdState;

struct Problem {
  const char* name;
  SrhdState left, right;
  double final_time;
};

std::string state_text(const SrhdState& s) {
  char b[128];
  std::snprintf(b, sizeof b, "[%.17g,%.17g,0,0,%.17g]", s.rho, s.v, s.p);
  return b;
}

// L1 norm of rho - rho_exact over [0, 1] at the final time.
double l1_error(const Problem& pb, int n, const std::string& reconstruction) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/shocktube_mm1.yaml";
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() / ("remnant_shocktube_" + std::to_string(::getpid()));
  o.overrides = {"Grid::ncells=[" + std::to_string(n) + ",1,1]", "Grid::block_size=[" + std::to_string(n / 4) + ",1,1]",
                 "GRMHD::shock_left=" + state_text(pb.left), "GRMHD::shock_right=" + state_text(pb.right),
                 "GRMHD::reconstruction=" + reconstruction, "MoL::final_time=" + std::to_string(pb.final_time),
                 "Flesh::out_dir=" + out.string()};
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  EXPECT_NEAR(sim.context().time(), pb.final_time, 1e-12);
  const ExactRiemannSRHD exact(5.0 / 3.0, pb.left, pb.right);
  using Prim = vars::HydroBase::prim;
  const int prim = sim.vars().find(Prim::full_name);
  double err = 0;
  for (Block* b : sim.grid()->local_blocks()) {
    const Field rho = Prim(*b, prim).field(Prim::idx::rho);
    for (int i = 0; i < b->n[0]; ++i)
      err += std::abs(rho(i, 0, 0) - exact.sample((b->x(0, i) - 0.5) / pb.final_time).rho) * b->dx[0];
  }
  return err;
}

void expect_convergence(const Problem& pb, const std::string& rec, int n0, double min_order, double max_l1_fine) {
  const double e1 = l1_error(pb, n0, rec), e2 = l1_error(pb, 2 * n0, rec), e3 = l1_error(pb, 4 * n0, rec);
  const double p12 = std::log2(e1 / e2), p23 = std::log2(e2 / e3);
  std::printf("%s (%s): L1(rho) %.4e %.4e %.4e at n = %d, %d, %d; orders %.3f %.3f\n", pb.name, rec.c_str(), e1, e2,
              e3, n0, 2 * n0, 4 * n0, p12, p23);
  EXPECT_GT(p12, min_order);
  EXPECT_GT(p23, min_order);
  EXPECT_LT(e3, max_l1_fine);
}

const Problem kProblem1{"Marti-Mueller 1", {10.0, 0.0, 13.33}, {1.0, 0.0, 1e-6}, 0.4};
const Problem kProblem2{"Marti-Mueller 2", {1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, 0.35};

}  // namespace

TEST(ExactRiemannSRHD, Problem1StarState) {
  // Marti & Mueller (2003), Table: p* = 1.448, v* = 0.714 for problem 1.
  const ExactRiemannSRHD e(5.0 / 3.0, kProblem1.left, kProblem1.right);
  EXPECT_NEAR(e.star_pressure(), 1.448, 2e-3);
  EXPECT_NEAR(e.star_velocity(), 0.714, 2e-3);
}

TEST(ShockTube, MartiMueller1PPM) { expect_convergence(kProblem1, "ppm", 100, 0.75, 0.03); }
TEST(ShockTube, MartiMueller1MC) { expect_convergence(kProblem1, "mc", 100, 0.7, 0.04); }
TEST(ShockTube, MartiMueller1Minmod) { expect_convergence(kProblem1, "minmod", 100, 0.6, 0.07); }
// The thin dense shell of problem 2 is resolved only beyond a few hundred cells.
TEST(ShockTube, MartiMueller2PPM) { expect_convergence(kProblem2, "ppm", 400, 0.5, 0.06); }
