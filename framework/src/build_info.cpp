#include "remnant/build_info.hpp"

#ifndef REMNANT_GIT_REVISION
#define REMNANT_GIT_REVISION "unknown"
#endif
#ifndef REMNANT_BUILD_TYPE
#define REMNANT_BUILD_TYPE "unknown"
#endif

namespace remnant {
const char* git_revision() { return REMNANT_GIT_REVISION; }
const char* build_type() { return REMNANT_BUILD_TYPE; }
}  // namespace remnant
