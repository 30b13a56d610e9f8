#pragma once
#include "remnant/context.hpp"

namespace remnant::tov {
// TOV_CheckParameters (paramcheck): throws InputError naming the parameters of a star that cannot make sense.
void check_parameters(Context& ctx);
}  // namespace remnant::tov
