// Static magnetised columns in cylindrical coordinates (R, z, phi): a uniform axial field B^z with a
// uniform pressure is an equilibrium whose flux divergence (p_tot through the exact face areas) and
// geometric source (alpha p_tot times the exact cell average of d ln sqrt f) cancel to round-off, in
// 2D and 3D (axis included); the velocities stay at round-off. The toroidal column
// (B^phi = b uniform, p = p0 - b^2 R^2: hoop stress and magnetic pressure against the pressure
// gradient) is an equilibrium of the continuum equations: its spurious velocities converge at second order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "remnant/coordinates.hpp"

#include "mhd_run.hpp"
#include "remnant/vars/HydroBase.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd::test;

// max over cells with x0_min <= x^0 <= x0_max of the physical speed sqrt(f_ii) |v^i| (flat space, psi = 1).
double max_speed(MhdRun& run, double x0_min = -1e300, double x0_max = 1e300) {
  using Prim = remnant::vars::HydroBase::prim;
  const int prim = run.group(Prim::full_name);
  double v = 0;
  for (Block* b : run.blocks()) {
    const Prim p(*b, prim);
    for_interior(*b, [&](int i, int j, int k) {
      if (b->x(0, i) < x0_min || b->x(0, i) > x0_max) return;
      const Point3 f = coords::metric_diagonal(b->coordinates, {b->x(0, i), b->x(1, j), b->x(2, k)});
      for (int c = 0; c < 3; ++c) {
        const double s = std::sqrt(f[c]) * std::abs(p.vel(c, i, j, k));
        v = std::max(v, s);
      }
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

// A uniform field along the Cartesian z axis through a uniform fluid at rest is an equilibrium. In
// spherical coordinates (r, theta) its components B^r = B cos theta, B^theta = -B sin theta / r vary,
// and the magnetic stress divergence must cancel the magnetic geometric sources (curvature terms of
// b^i b^j, p_tot) including at the axis and the origin: the spurious velocity converges.
TEST(MHDEquilibrium, UniformFieldInSphericalCoordinatesConverges) {
  double v[2], v_origin[2];
  for (int q = 0; q < 2; ++q) {
    const int n = 16 << q;
    const std::string grid = "coordinates: spherical, dimension: 2, ncells: [" + std::to_string(n) + ", " + std::to_string(n) +
                             ", 1], block_size: [8, 8, 1], xmin: [0, 0, 0], xmax: [1, 3.141592653589793, 1], "
                             "ghost_zones: 3, boundary_lower: [origin, axis, outflow], boundary_upper: [outflow, axis, outflow]";
    MhdRun run(mhd_parfile(grid,
                           "reconstruction: ppm, initial_data: shock_tube, shock_position: 2.0, "
                           "shock_left: [1.0, 0.0, 0.0, 0.0, 0.5], shock_right: [1.0, 0.0, 0.0, 0.0, 0.5], "
                           "field_potential: uniform_z, field_potential_amplitude: 1.0",
                           "cfl: 0.4, final_time: 0.1"));
    v[q] = max_speed(run, 0.25, 0.75);  // the outflow boundary at r = 1 (zero gradient of B^theta ~ 1/r) is not an equilibrium
    v_origin[q] = max_speed(run);
  }
  const double order = std::log2(v[0] / v[1]);
  std::printf("spherical 2D, uniform B^z = 1 (b^2/2p = 1): max |v| at t = 0.1 for 1/4 < r < 3/4: %.3e (16^2), %.3e (32^2), order %.2f; "
              "everywhere (the outflow boundary at r = 1): %.3e, %.3e\n", v[0], v[1], order, v_origin[0], v_origin[1]);
  EXPECT_GT(order, 1.8);
  EXPECT_LT(v[1], 5e-3);
  EXPECT_LT(v_origin[1], 0.03);  // the outflow boundary, no equilibrium; the origin: test_mhd_axis.cpp
}
