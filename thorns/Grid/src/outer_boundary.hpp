#pragma once
// Boundary conditions on non-periodic domain faces, after the ghost exchange.
#include <span>

#include "block_layout.hpp"

namespace remnant::grid {

// Applies direction after direction (x, then y, then z), each over the full extent of the other
// directions including their ghosts, so that edges and corners end up as if the conditions were
// applied to an infinitely fine face by face: later directions overwrite the corner ghosts from
// values the earlier directions (or the exchange) already set. Cell-centred groups only.
void apply_outer_boundaries(Block& block, const BlockLayout& layout, const UniformGridConfig& config,
                            const VariableRegistry& vars, std::span<const int> groups);

}  // namespace remnant::grid
