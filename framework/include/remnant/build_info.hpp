#pragma once
// Provenance of this build, written into every output file and checkpoint.
namespace remnant {
const char* git_revision();
const char* build_type();
}  // namespace remnant
