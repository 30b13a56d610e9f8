// Static magnetised columns in cylindrical coordinates (R, z, phi): a uniform axial field B^z with a
// uniform pressure is an equilibrium whose flux divergence (p_tot through the exact face areas) and
// geometric source (alpha p_tot times the exact cell average of d ln sqrt f) cancel to round-off, in
// 2D and 3D (axis included); the velocities stay at round-off. The toroidal column
// (B^phi = b uniform, p = p0 - b^2 R^2: hoop stress and magnetic pressure against the pressure
// gradient) is an equilibrium of the continuum equations: its spurious velocities converge at second order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mhd_run.hpp"
#include "remnant/vars/HydroBase.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd::test;

double max_speed(MhdRun& run) {
  using Prim = remnant::vars::HydroBase::prim;
  const int prim = run.group(Prim::full_name);
  double v = 0;
  for (Block* b : run.blocks()) {
    const Prim p(*b, prim);
    for_interior(*b, [&](int i, int j, int k) {
      for (int c = 0; c < 3; ++c) v = std::max(v, std::abs(p.vel(c, i, j, k)));
    });
  }
  return v;
}

std::string column(int dim, int n) {
  return "coordinates: cylindrical, dimension: " + std::to_string(dim) + ", ncells: [" + std::to_string(n) + ", " +
         std::to_string(n) + ", " + (dim == 3 ? "16" : "1") + "], block_size: [8, 8, " + (dim == 3 ? "8" : "1") +
         "], xmin: [0, -0.5, 0], xmax: [1, 0.5, 6.283185307179586], ghost_zones: 3, "
         "boundary_lower: [axis, periodic, periodic], boundary_upper: [outflow, periodic, periodic]";
}

}  // namespace

TEST(MHDEquilibrium, UniformAxialFieldColumnStaysStaticToRoundOff) {
  for (int dim : {2, 3}) {
    MhdRun run(mhd_parfile(column(dim, 16),
                           "reconstruction: ppm, initial_data: shock_tube, shock_position: 2.0, "
                           "shock_left: [1.0, 0.0, 0.0, 0.0, 0.1], shock_right: [1.0, 0.0, 0.0, 0.0, 0.1], "
                           "shock_field_left: [0.0, 2.0, 0.0], shock_field_right: [0.0, 2.0, 0.0]",
                           "cfl: 0.4, max_iterations: 20"));
    const double v = max_speed(run);
    std::printf("cylindrical %dD, uniform B^z = 2, p = 0.1 (b^2/2p = 20): max |v| after 20 steps %.2e\n", dim, v);
    EXPECT_LT(v, 1e-14);
  }
}
