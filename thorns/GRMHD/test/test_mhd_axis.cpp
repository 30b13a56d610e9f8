// probe (temporary)
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

void report(MhdRun& run, const char* what) {
  using Prim = remnant::vars::HydroBase::prim;
  const int prim = run.group(Prim::full_name);
  double v = 0, vm = 0;
  int at[4] = {0, 0, 0, 0};
  for (Block* b : run.blocks()) {
    const Prim p(*b, prim);
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 f = coords::metric_diagonal(b->coordinates, {b->x(0, i), b->x(1, j), b->x(2, k)});
      for (int c = 0; c < 3; ++c) {
        const double s = std::sqrt(f[c]) * std::abs(p.vel(c, i, j, k));
        if (s > v) {
          v = s;
          at[0] = int(std::lround((b->x(0, i) - 0.5 * b->dx[0]) / b->dx[0])); at[1] = int(std::lround((b->x(1, j) - 0.5 * b->dx[1]) / b->dx[1])); at[2] = int(std::lround((b->x(2, k) - 0.5 * b->dx[2]) / b->dx[2])); at[3] = c;
        }
        if (b->x(0, i) > 0.25 && b->x(0, i) < 0.75) vm = std::max(vm, s);
      }
    });
  }
  std::printf("== %s\n", what);
  if (std::getenv("PROBE_PROFILE"))
    for (Block* b : run.blocks()) {
      const Prim p(*b, prim);
      for_interior(*b, [&](int i, int j, int k) {
        if (b->x(0, i) > 1.5 * b->dx[0] || (b->coordinates == CoordinateSystem::cylindrical ? (j > 0 || b->lo[1] > -0.49) : k > 0)) return;
        const Point3 f = coords::metric_diagonal(b->coordinates, {b->x(0, i), b->x(1, j), b->x(2, k)});
        std::printf("  i%d x1 %.3f: a = %+.3e %+.3e %+.3e\n", int(b->x(0, i) / b->dx[0]), b->x(b->coordinates == CoordinateSystem::cylindrical ? 2 : 1, b->coordinates == CoordinateSystem::cylindrical ? k : j),
                    std::sqrt(f[0]) * p.vel(0, i, j, k) / 1e-4, std::sqrt(f[1]) * p.vel(1, i, j, k) / 1e-4,
                    std::sqrt(f[2]) * p.vel(2, i, j, k) / 1e-4);
      });
    }
  std::printf("%s: max|v| %.3e at (%d,%d,%d) comp %d; 1/4<r<3/4 %.3e\n", what, v, at[0], at[1], at[2], at[3], vm);
}

std::string sph(int n) {
  return "coordinates: spherical, dimension: 2, ncells: [" + std::to_string(n) + ", " + std::to_string(n) +
         ", 1], block_size: [8, 8, 1], xmin: [0, 0, 0], xmax: [1, 3.141592653589793, 1], "
         "ghost_zones: 3, boundary_lower: [origin, axis, outflow], boundary_upper: [outflow, axis, outflow]";
}
std::string cyl3(int n) {
  return "coordinates: cylindrical, dimension: 3, ncells: [" + std::to_string(n) + ", 8, " + std::to_string(n) +
         "], block_size: [8, 8, 8], xmin: [0, -0.5, 0], xmax: [1, 0.5, 6.283185307179586], ghost_zones: 3, "
         "boundary_lower: [axis, periodic, periodic], boundary_upper: [outflow, periodic, periodic]";
}
const char* kFluid = "reconstruction: ppm, initial_data: shock_tube, shock_position: 2.0, "
                     "shock_left: [1.0, 0.0, 0.0, 0.0, 0.5], shock_right: [1.0, 0.0, 0.0, 0.0, 0.5], ";

}  // namespace

TEST(MHDAxisProbe, Probe) {
  const char* it = std::getenv("PROBE_MOL");
  const std::string mol = it ? it : "cfl: 0.4, final_time: 0.1";
  std::vector<std::string> ov;
  if (std::getenv("PROBE_EULER")) ov.push_back("MoL::method=euler");
  for (int n : {16, 32}) {
    {
      MhdRun run(mhd_parfile(sph(n), std::string(kFluid) + "field_potential: uniform_z, field_potential_amplitude: 1.0", mol), ov);
      report(run, ("sph uniform_z n=" + std::to_string(n)).c_str());
    }
    {
      MhdRun run(mhd_parfile(sph(n), std::string(kFluid) + "field_potential: uniform_x, field_potential_amplitude: 1.0", mol), ov);
      report(run, ("sph uniform_x(2D) n=" + std::to_string(n)).c_str());
    }
    {
      MhdRun run(mhd_parfile(cyl3(n), std::string(kFluid) + "field_potential: uniform_x, field_potential_amplitude: 1.0", mol), ov);
      report(run, ("cyl3 uniform_x n=" + std::to_string(n)).c_str());
    }
  }
}
