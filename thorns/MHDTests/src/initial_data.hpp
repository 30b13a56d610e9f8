#pragma once
// The problem's primitives (flat space: W from v) and face fields on every local block.
#include "remnant/context.hpp"

namespace remnant::mhd_tests {
void initial_primitives(Context& ctx);
// Writes HydroBase::Bface1..3 (only scheduled with HydroBase::magnetic_field = evolved).
void initial_face_fields(Context& ctx);
}  // namespace remnant::mhd_tests
