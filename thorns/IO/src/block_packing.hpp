#pragma once
// The points of a block that a checkpoint stores for a group: the interior, plus the upper face
// of staggered centerings in used directions (ghosts are rebuilt by the next synchronisation).
// Order: component, then k, j, i (i fastest).
#include <cstddef>
#include <vector>

#include "remnant/grid.hpp"

namespace remnant::io {

std::size_t packed_size(const Block& b, const VariableGroupSpec& spec, int dimension);
void pack(Block& b, const VariableGroupSpec& spec, int dimension, std::vector<double>& out);  // appends
void unpack(Block& b, const VariableGroupSpec& spec, int dimension, const double* in);

}  // namespace remnant::io
