#pragma once
#include <string>

#include "remnant/context.hpp"

namespace remnant::seed {
// SeedMagneticField_CheckParameters (paramcheck): throws InputError naming the parameter when the
// run has no evolved B, p_cut_fraction >= 1, or the grid has no axis for a star's field.
void check_parameters(Context& ctx);

// The atmosphere's cap on the magnetisation b^2/rho (Thorn, name): the seeded field must stay below
// it in the star (checked when the active thorns declare it; see README.md).
inline constexpr const char* kMagnetisationCapThorn = "Atmosphere";
inline constexpr const char* kMagnetisationCapName = "sigma_max";
}  // namespace remnant::seed
