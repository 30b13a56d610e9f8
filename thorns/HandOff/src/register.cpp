// HandOff's scheduled functions.
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"

REMNANT_REGISTER_THORN(HandOff) {}
