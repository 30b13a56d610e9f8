// MHDTests: initial data of the standard relativistic MHD test problems.
#include "check_parameters.hpp"
#include "initial_data.hpp"
#include "remnant/registrar.hpp"

REMNANT_REGISTER_THORN(MHDTests) {
  using namespace remnant::mhd_tests;
  reg.function("MHDTests_CheckParameters", check_parameters);
  reg.function("MHDTests_InitialPrimitives", initial_primitives);
}
