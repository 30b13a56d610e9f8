#pragma once
// RotatingStar_CheckParameters (check_field.cpp): a magnetised equilibrium needs evolved B and
// SeedMagneticField's toroidal law with the same K_m and m.
#include "remnant/context.hpp"

namespace remnant::rotstar {
void check_field_parameters(Context& ctx);
}
