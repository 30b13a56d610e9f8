#include "remnant/build_info.hpp"

// git_revision() is generated at build time (cmake/GitRevision.cmake).
#ifndef REMNANT_BUILD_TYPE
#define REMNANT_BUILD_TYPE "unknown"
#endif

namespace remnant {
const char* build_type() { return REMNANT_BUILD_TYPE; }
}  // namespace remnant
