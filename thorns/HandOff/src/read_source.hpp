#pragma once
// HandOff's parameters to a complete SourceData: the reader of HandOff::format, the magnetic-field
// check, the EOS mappings of missing variables and the densitised conserved variables.
#include <memory>
#include <string>
#include <vector>

#include "HandOff/source_data.hpp"
#include "remnant/context.hpp"

namespace remnant::handoff {

std::shared_ptr<SourceData> read_source(const Context& ctx, std::vector<std::string>& notes);

}  // namespace remnant::handoff
