// MHDTests: initial data of the standard relativistic MHD test problems.
#include "check_parameters.hpp"
#include "diagnostics.hpp"
#include "initial_data.hpp"
#include "remnant/registrar.hpp"

REMNANT_REGISTER_THORN(MHDTests) {
  using namespace remnant::mhd_tests;
  reg.function("MHDTests_CheckParameters", check_parameters);
  reg.function("MHDTests_InitialPrimitives", initial_primitives);
  reg.function("MHDTests_InitialFaceFields", initial_face_fields);
  reg.function("MHDTests_Diagnostics", magnetic_diagnostics);
}
