#pragma once
#include "remnant/context.hpp"

namespace remnant::handoff {
void check_parameters(Context& ctx);
void initial(Context& ctx);
void import_conserved(Context& ctx);
void report(Context& ctx);
void magnetic_field(Context& ctx);   // HandOff_MagneticField (magnetic_import.hpp)
void magnetic_report(Context& ctx);  // HandOff_MagneticReport: E_mag with the solved psi
}  // namespace remnant::handoff
