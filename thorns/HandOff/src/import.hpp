#pragma once
#include "remnant/context.hpp"

namespace remnant::handoff {
void check_parameters(Context& ctx);
void initial(Context& ctx);
void import_conserved(Context& ctx);
void report(Context& ctx);
}  // namespace remnant::handoff
