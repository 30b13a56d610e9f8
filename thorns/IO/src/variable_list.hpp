#pragma once
// Resolves a parameter's list of "Thorn::group" (every component) or "Thorn::group.component"
// into (group, component) pairs, with errors naming the parameter and the valid groups.
#include <string>
#include <vector>

#include "remnant/context.hpp"

namespace remnant::io {

struct VariableRef {
  int group = -1;
  int comp = 0;
  std::string full;  // "WaveToy::wave.u"
  std::string file;  // "WaveToy-wave.u": usable in file and HDF5 names (no "::")
  // Grid output of a face-centred group: the direction whose two faces are averaged into each
  // cell (-1: cell-centred, written as is) and the note marking the data ("cell average of face_x").
  int average_direction = -1;
  std::string centering_note;
};

std::vector<VariableRef> resolve_variables(const Context& ctx, const std::string& param,
                                           const std::vector<std::string>& names);

}  // namespace remnant::io
