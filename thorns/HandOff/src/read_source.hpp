#pragma once
// HandOff's parameters to a complete SourceData: the reader of HandOff::format, the magnetic-field
// check, the EOS mappings of missing variables and the densitised conserved variables.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "HandOff/source_data.hpp"
#include "remnant/context.hpp"

namespace remnant::handoff {

std::shared_ptr<SourceData> read_source(const Context& ctx, std::vector<std::string>& notes);

// The mirror planes HandOff::reflection names (the files may declare more).
std::array<bool, 3> reflection_parameter(const Parameters& p);

// HandOff::centre against the data's mirror planes x^d = 0: unfolded data are symmetric about each,
// so the remnant's centre lies on it and a non-zero component along a mirrored axis is an input
// error. mirrors: the unfolded planes; from_files: those the files declared (not HandOff::reflection).
void check_centre_on_mirrors(const Parameters& p, const std::array<bool, 3>& mirrors,
                             const std::array<bool, 3>& from_files = {false, false, false});

}  // namespace remnant::handoff
