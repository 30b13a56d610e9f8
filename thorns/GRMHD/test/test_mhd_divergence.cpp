// Constrained transport keeps div B at round-off: a moving magnetised flow (a shock tube with
// transverse velocities, plus the smooth test vector potential of shock_tube_field.hpp) evolved for
// some steps in Cartesian 1D-3D, cylindrical 2D/3D and spherical 2D/3D, with a refined region
// (Grid::correct_edges) in most. Checked globally (magnetic_flux_check.hpp): each cell's divergence,
// the faces shared by blocks, the coarse faces against their fine faces; both EMF schemes.
#include <gtest/gtest.h>

#include <cstdio>

#include "magnetic_flux_check.hpp"
#include "mhd_run.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;
using namespace remnant::grmhd::test;

struct Case {
  const char* name;
  std::string grid;
  double amplitude;
};

// periodic_cells: level-0 cells of the periodic directions (the check then also compares the faces
// through the periodic seam); potential: GRMHD::field_potential.
void expect_divergence_free(const Case& c, const std::string& emf, int steps = 12,
                            std::array<long long, 3> periodic_cells = {0, 0, 0},
                            const std::string& potential = "smooth_test", const std::string& edges = "mc") {
  const std::string grmhd = "reconstruction: ppm, emf: " + emf + ", emf_reconstruction: " + edges +
                            ", initial_data: shock_tube, shock_position: 0.55, "
                            "shock_left: [1.0, 0.3, 0.2, 0.1, 1.0], shock_right: [0.2, -0.2, 0.1, -0.3, 0.1], "
                            "shock_field_left: [0.0, 0.0, 0.0], shock_field_right: [0.0, 0.0, 0.0], "
                            "field_potential: " + potential + ", field_potential_amplitude: " + std::to_string(c.amplitude);
  MhdRun run(mhd_parfile(c.grid, grmhd, "cfl: 0.3, max_iterations: " + std::to_string(steps)));
  MhdGroups g;
  for (int d = 0; d < 3; ++d) g.bface[d] = run.group("HydroBase::Bface" + std::to_string(d + 1));
  const FluxCheck r = check_magnetic_flux(g, run.blocks(), periodic_cells);
  std::printf("%s (%s): cell div %.2e, shared faces %.2e, coarse/fine %.2e over %d coarse faces\n", c.name,
              emf.c_str(), r.cell, r.shared, r.coarse_fine, r.coarse_faces);
  EXPECT_LT(r.cell, 1e-12);
  EXPECT_LT(r.shared, 1e-13);
  EXPECT_LT(r.coarse_fine, 1e-13);
}

const std::string kOutflow = "boundary_lower: [outflow, outflow, outflow], boundary_upper: [outflow, outflow, outflow]";

const Case kCartesian2D{"Cartesian 2D, refined box",
                        "dimension: 2, ncells: [32, 32, 1], block_size: [8, 8, 1], xmin: [0, 0, 0], xmax: [1, 1, 1], "
                        "ghost_zones: 3, " + kOutflow +
                            ", max_level: 1, regions: [box], region_levels: [1], region_bounds: [0.4, 0.7, 0.3, 0.6, -1, 2]",
                        0.05};

const Case kCartesian3D{"Cartesian 3D, refined box",
                        "dimension: 3, ncells: [16, 16, 16], block_size: [8, 8, 8], xmin: [0, 0, 0], xmax: [1, 1, 1], "
                        "ghost_zones: 3, " + kOutflow +
                            ", max_level: 1, regions: [box], region_levels: [1], region_bounds: [0.1, 0.2, 0.1, 0.2, 0.1, 0.2]",
                        0.05};

const Case kSpherical2D{"spherical 2D, refined box",
                        "coordinates: spherical, dimension: 2, ncells: [32, 32, 1], block_size: [8, 8, 1], "
                        "xmin: [0, 0, 0], xmax: [1, 3.141592653589793, 1], ghost_zones: 3, "
                        "boundary_lower: [origin, axis, outflow], boundary_upper: [outflow, axis, outflow], "
                        "max_level: 1, regions: [box], region_levels: [1], region_bounds: [0.5, 0.8, 0.0, 0.5, -10, 10]",
                        0.1};

}  // namespace

TEST(MHDDivergence, Cartesian1D) {
  expect_divergence_free({"Cartesian 1D", "dimension: 1, ncells: [64, 1, 1], block_size: [16, 1, 1], xmin: [0, 0, 0], "
                                          "xmax: [1, 1, 1], ghost_zones: 3, " + kOutflow, 0.05},
                         "uct_hll");
}

TEST(MHDDivergence, Cartesian2DRefinedUct) { expect_divergence_free(kCartesian2D, "uct_hll"); }
TEST(MHDDivergence, Cartesian2DRefinedArithmetic) { expect_divergence_free(kCartesian2D, "arithmetic"); }
TEST(MHDDivergence, Cartesian2DRefinedContact) { expect_divergence_free(kCartesian2D, "uct_contact"); }

TEST(MHDDivergence, Cartesian3DRefined) {
  expect_divergence_free(kCartesian3D,
                         "uct_hll", 6);
}

// The PPM edge states read a third ghost layer of the face fields (refinement boundaries included).
TEST(MHDDivergence, Cartesian3DRefinedPpmEpEdges) { expect_divergence_free(kCartesian3D, "uct_hll", 6, {0, 0, 0}, "smooth_test", "ppm_ep"); }

TEST(MHDDivergence, Cartesian3DRefinedContact) {
  expect_divergence_free(kCartesian3D,
                         "uct_contact", 6);
}

// Cylindrical (R, z, phi): the axis R = 0 (zero-area faces, zero-length edges), phi periodic in 3D.
TEST(MHDDivergence, Cylindrical2DRefined) {
  expect_divergence_free({"cylindrical 2D, refined box",
                          "coordinates: cylindrical, dimension: 2, ncells: [32, 32, 1], block_size: [8, 8, 1], "
                          "xmin: [0, -0.5, 0], xmax: [1, 0.5, 1], ghost_zones: 3, "
                          "boundary_lower: [axis, outflow, outflow], boundary_upper: [outflow, outflow, outflow], "
                          "max_level: 1, regions: [box], region_levels: [1], region_bounds: [0.0, 0.2, -0.2, 0.1, -10, 10]",
                          0.1},
                         "uct_hll");
}

TEST(MHDDivergence, Cylindrical2DRefinedPpmEpEdges) {
  expect_divergence_free({"cylindrical 2D, refined box, ppm_ep edges",
                          "coordinates: cylindrical, dimension: 2, ncells: [32, 32, 1], block_size: [8, 8, 1], "
                          "xmin: [0, -0.5, 0], xmax: [1, 0.5, 1], ghost_zones: 3, "
                          "boundary_lower: [axis, outflow, outflow], boundary_upper: [outflow, outflow, outflow], "
                          "max_level: 1, regions: [box], region_levels: [1], region_bounds: [0.0, 0.2, -0.2, 0.1, -10, 10]",
                          0.1},
                         "uct_hll", 12, {0, 0, 0}, "smooth_test", "ppm_ep");
}

TEST(MHDDivergence, Spherical2DRefinedContact) {
  expect_divergence_free(kSpherical2D,
                         "uct_contact");
}

TEST(MHDDivergence, Cylindrical3D) {
  expect_divergence_free({"cylindrical 3D, phi periodic",
                          "coordinates: cylindrical, dimension: 3, ncells: [16, 8, 16], block_size: [8, 8, 8], "
                          "xmin: [0, -0.5, 0], xmax: [1, 0.5, 6.283185307179586], ghost_zones: 3, "
                          "boundary_lower: [axis, outflow, periodic], boundary_upper: [outflow, outflow, periodic]",
                          0.1},
                         "uct_hll", 6, {0, 0, 16});
}

// A refined region touching the axis over half the phi range: across the axis of its coarse
// neighbours lies fine mesh, and the fine region's phi = 0 side meets coarse blocks through the
// periodic seam.
TEST(MHDDivergence, Cylindrical3DRefinedHalfAroundTheAxis) {
  expect_divergence_free({"cylindrical 3D, refined phi in [0, pi] at the axis",
                          "coordinates: cylindrical, dimension: 3, ncells: [16, 8, 16], block_size: [8, 8, 8], "
                          "xmin: [0, -0.5, 0], xmax: [1, 0.5, 6.283185307179586], ghost_zones: 3, "
                          "boundary_lower: [axis, outflow, periodic], boundary_upper: [outflow, outflow, periodic], "
                          "max_level: 1, regions: [box], region_levels: [1], region_bounds: [0.0, 0.3, -0.2, 0.2, 0.0, 3.0]",
                          0.1},
                         "uct_hll", 3, {0, 0, 16});
}

// uniform_z: A_phi only (for smooth_test and uniform_x at t = 0 see
// Spherical3DRefinedInitialFacesMatchAcrossLevels).
TEST(MHDDivergence, Spherical3DRefinedHalfAroundThePolarAxis) {
  expect_divergence_free({"spherical 3D, refined phi in [0, pi] at the axis",
                          "coordinates: spherical, dimension: 3, ncells: [16, 8, 16], block_size: [8, 8, 8], "
                          "xmin: [0, 0, 0], xmax: [1, 3.141592653589793, 6.283185307179586], ghost_zones: 3, "
                          "boundary_lower: [origin, axis, periodic], boundary_upper: [outflow, axis, periodic], "
                          "max_level: 1, regions: [box], region_levels: [1], region_bounds: [0.6, 0.9, 0.0, 0.3, 0.0, 3.0]",
                          0.1},
                         "uct_hll", 3, {0, 0, 16}, "uniform_z");
}

// The initial faces alone (no step): on a refined 3D spherical grid the coarse faces carry exactly
// their fine faces' summed flux, for a potential with A_r, A_phi (smooth_test) and with A_r, A_theta
// (uniform_x) -- the edge integrals must be accurate, not midpoint (4.2e-5 and 2.3e-3 of the flux).
TEST(MHDDivergence, Spherical3DRefinedInitialFacesMatchAcrossLevels) {
  const Case c{"spherical 3D refined, t = 0",
               "coordinates: spherical, dimension: 3, ncells: [16, 16, 32], block_size: [8, 8, 8], "
               "xmin: [0, 0, 0], xmax: [1, 3.141592653589793, 6.283185307179586], ghost_zones: 3, "
               "boundary_lower: [origin, axis, periodic], boundary_upper: [outflow, axis, periodic], "
               "max_level: 1, regions: [box], region_levels: [1], region_bounds: [0.6, 0.9, 0.2, 1.2, 0.5, 3.0]",
               0.1};
  for (const char* potential : {"smooth_test", "uniform_x"}) expect_divergence_free(c, "uct_hll", 0, {0, 0, 32}, potential);
}

// Spherical (r, theta, phi): the origin, both axis ends, phi periodic in 3D.
TEST(MHDDivergence, Spherical2DRefined) {
  expect_divergence_free(kSpherical2D,
                         "uct_hll");
}

TEST(MHDDivergence, Spherical3D) {
  expect_divergence_free({"spherical 3D, phi periodic",
                          "coordinates: spherical, dimension: 3, ncells: [16, 8, 16], block_size: [8, 8, 8], "
                          "xmin: [0, 0, 0], xmax: [1, 3.141592653589793, 6.283185307179586], ghost_zones: 3, "
                          "boundary_lower: [origin, axis, periodic], boundary_upper: [outflow, axis, periodic]",
                          0.1},
                         "uct_hll", 6, {0, 0, 16});
}

// Adaptive refinement following the shock (Löhner on rho, regrid every step): the divergence stays
// at round-off across regrids (divergence-preserving prolongation of the faces), and Bvec of every
// cell is the area-weighted mean of its faces right after the last regrid (post_regrid), not a
// linear prolongation of Bvec.
TEST(MHDDivergence, Cartesian2DAdaptiveRegrids) {
  const std::string grid = "dimension: 2, ncells: [32, 32, 1], block_size: [8, 8, 1], xmin: [0, 0, 0], xmax: [1, 1, 1], "
                           "ghost_zones: 3, " + kOutflow +
                           ", max_level: 1, regrid_every: 1, refine_variable: HydroBase::prim.rho, refine_threshold: 0.1";
  const std::string grmhd = "reconstruction: ppm, initial_data: shock_tube, shock_position: 0.35, "
                            "shock_left: [1.0, 0.6, 0.2, 0.1, 1.0], shock_right: [0.2, 0.0, 0.1, -0.3, 0.1], "
                            "field_potential_amplitude: 0.05";
  for (int steps : {6, 9}) {  // both end with a regrid that made new blocks (1.5e-2, 2e-3 without post_regrid)
  MhdRun run(mhd_parfile(grid, grmhd, "cfl: 0.3, max_iterations: " + std::to_string(steps)));
  MhdGroups g;
  for (int d = 0; d < 3; ++d) g.bface[d] = run.group("HydroBase::Bface" + std::to_string(d + 1));
  const FluxCheck r = check_magnetic_flux(g, run.blocks());
  const int bvec = run.group("HydroBase::Bvec");
  double worst = 0;
  int levels[2] = {0, 0};
  for (Block* b : run.blocks()) {
    ++levels[std::min(b->level, 1)];
    for_interior(*b, [&](int i, int j, int k) {
      for (int a = 0; a < 2; ++a) {
        const Field f = b->field(g.bface[a], 0);
        int up[3] = {i, j, k};
        ++up[a];
        const double am = b->face_area(a, i, j, k), ap = b->face_area(a, up[0], up[1], up[2]);
        const double expect = (am * f(i, j, k) + ap * f(up[0], up[1], up[2])) / (am + ap);  // psi = 1
        worst = std::max(worst, std::abs(b->field(bvec, a)(i, j, k) - expect));
      }
    });
  }
  std::printf("adaptive 2D: %d coarse and %d fine blocks, cell div %.2e, coarse/fine %.2e over %d faces, max |Bvec - faces| %.2e\n",
              levels[0], levels[1], r.cell, r.coarse_fine, r.coarse_faces, worst);
  EXPECT_GT(levels[1], 0);
  EXPECT_GT(levels[0], 0);
  EXPECT_LT(r.cell, 1e-12);
  EXPECT_LT(r.coarse_fine, 1e-13);
  EXPECT_LT(worst, 1e-14);
  }
}
