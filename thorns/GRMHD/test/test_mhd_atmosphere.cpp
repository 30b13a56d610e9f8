// The atmosphere with a magnetic field: cells reset to the atmosphere keep their B, and their
// magnetisation b^2/rho is capped at Atmosphere::sigma_max by raising rho (recovery sweeps and
// initial data); initial data whose b^2/rho exceeds the cap outside the atmosphere is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mhd_run.hpp"
#include "remnant/error.hpp"
#include "remnant/vars/HydroBase.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd::test;

const std::string kGrid = "dimension: 1, ncells: [64, 1, 1], block_size: [16, 1, 1], xmin: [0, 0, 0], xmax: [1, 1, 1], "
                          "ghost_zones: 3, boundary_lower: [outflow, outflow, outflow], boundary_upper: [outflow, outflow, outflow]";

}  // namespace

TEST(MHDAtmosphere, MagnetisationOfAtmosphereCellsIsCapped) {
  // A dense slab (x < 0.5) and an empty right half (rho below rho_thr = 1e-10), both threaded by
  // B^2 = 0.1 (b^2 = 0.01): without the cap the atmosphere would have b^2/rho ~ 1e8.
  MhdRun run(mhd_parfile(kGrid,
                         "reconstruction: mc, initial_data: shock_tube, shock_position: 0.5, "
                         "shock_left: [1.0, 0.0, 0.0, 0.0, 0.1], shock_right: [1.0e-12, 0.0, 0.0, 0.0, 1.0e-14], "
                         "shock_field_left: [0.0, 0.1, 0.0], shock_field_right: [0.0, 0.1, 0.0]",
                         "cfl: 0.4, max_iterations: 10"),
             {"Atmosphere::sigma_max=50"});
  using Prim = vars::HydroBase::prim;
  const int prim = run.group(Prim::full_name), bvec = run.group("HydroBase::Bvec");
  double worst = 0, rho_min = 1e300;
  int capped = 0;
  for (Block* b : run.blocks()) {
    const Prim p(*b, prim);
    for (int i = 0; i < b->n[0]; ++i) {
      if (b->x(0, i) < 0.8) continue;  // far from the slab's expansion after 10 steps
      const double W = p.W(i, 0, 0), By = b->field(bvec, 1)(i, 0, 0);
      const double b2 = By * By / (W * W);
      worst = std::max(worst, b2 / p.rho(i, 0, 0));
      rho_min = std::min(rho_min, p.rho(i, 0, 0));
      ++capped;
    }
  }
  std::printf("atmosphere with B^2 = 0.1: %d cells, max b^2/rho %.6g (cap 50), min rho %.3e\n", capped, worst, rho_min);
  ASSERT_GT(capped, 5);
  EXPECT_LE(worst, 50 * (1 + 1e-12));
  EXPECT_NEAR(rho_min, 0.01 / 50, 1e-12);
}

TEST(MHDAtmosphere, TooStrongInitialFieldIsRefused) {
  // b^2/rho = 1600 in the dense slab, above the default cap of 1000.
  try {
    MhdRun run(mhd_parfile(kGrid,
                           "reconstruction: mc, initial_data: shock_tube, shock_position: 0.5, "
                           "shock_left: [1.0, 0.0, 0.0, 0.0, 0.1], shock_right: [1.0, 0.0, 0.0, 0.0, 0.1], "
                           "shock_field_left: [0.0, 40.0, 0.0], shock_field_right: [0.0, 40.0, 0.0]",
                           "cfl: 0.4, max_iterations: 1"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("Atmosphere::sigma_max"), std::string::npos) << m;
    EXPECT_NE(m.find("b^2/rho = 1600"), std::string::npos) << m;
  }
}

// A magnetic-field parameter without a field is refused before the first step, naming it.
TEST(MHDParameters, FieldParameterWithoutFieldIsAnError) {
  std::string par = mhd_parfile(kGrid,
                                "reconstruction: mc, initial_data: shock_tube, "
                                "shock_field_left: [0.0, 1.0, 0.0], shock_field_right: [0.0, 1.0, 0.0]",
                                "cfl: 0.4, max_iterations: 1");
  par.replace(par.find("magnetic_field: evolved"), 23, "magnetic_field: none");
  try {
    MhdRun run(par);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("GRMHD::shock_field_left is a magnetic-field parameter"), std::string::npos) << m;
    EXPECT_NE(m.find("run.yaml:"), std::string::npos) << m;
  }
}

// GRMHD::emf_reconstruction: refused without a field; a PPM edge reconstruction needs 3 ghost zones.
TEST(MHDParameters, EmfReconstructionErrors) {
  std::string par = mhd_parfile(kGrid, "reconstruction: mc, emf_reconstruction: ppm, initial_data: shock_tube",
                                "cfl: 0.4, max_iterations: 1");
  std::string none = par;
  none.replace(none.find("magnetic_field: evolved"), 23, "magnetic_field: none");
  try {
    MhdRun run(none);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("GRMHD::emf_reconstruction is a magnetic-field parameter"), std::string::npos) << m;
  }
  std::string two = par;
  two.replace(two.find("ghost_zones: 3"), 14, "ghost_zones: 2");
  try {
    MhdRun run(two);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("GRMHD::emf_reconstruction = ppm needs 3 ghost zones; Grid::ghost_zones is 2"), std::string::npos) << m;
    EXPECT_NE(m.find("run.yaml:"), std::string::npos) << m;
  }
}
