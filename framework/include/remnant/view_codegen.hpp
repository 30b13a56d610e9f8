#pragma once
// Generates the named-view header of a thorn (<remnant/vars/<Thorn>.hpp>) from its thorn.yaml:
// per variable group a GroupView with component indices and accessors named after the declared
// tensors. CMake runs it through the `remnant-genviews` tool at build time.
#include <string>

#include "remnant/thorn_spec.hpp"

namespace remnant {

// Throws InputError (naming the thorn.yaml) when a group or component name cannot be a C++ name.
std::string generate_view_header(const ThornSpec& spec);

}  // namespace remnant
