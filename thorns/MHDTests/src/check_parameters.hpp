#pragma once
#include "remnant/context.hpp"

namespace remnant::mhd_tests {
void check_parameters(Context& ctx);
}  // namespace remnant::mhd_tests
