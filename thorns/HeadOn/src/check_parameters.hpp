#pragma once
#include "remnant/context.hpp"

namespace remnant::headon {
// HeadOn_CheckParameters (paramcheck): throws InputError naming the parameters of a binary that cannot make sense.
void check_parameters(Context& ctx);
}  // namespace remnant::headon
