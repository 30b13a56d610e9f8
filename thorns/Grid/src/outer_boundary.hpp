#pragma once
// Outflow (zero-gradient extrapolation) on domain faces, after the ghost exchange, followed by the
// thorns' own conditions on their groups there (GridDriver::add_outflow_condition). Every other
// condition (periodic, reflect, axis, origin) is a boundary map that the exchange applies.
#include <map>
#include <span>
#include <vector>

#include "forest.hpp"

namespace remnant::grid {

// Applies direction after direction (x, then y, then z), each over the full extent of the other
// directions including their ghosts, so that edges and corners end up as if the conditions were
// applied face by face: later directions overwrite corner ghosts from values the earlier
// directions (or the exchange) already set. A group's conditions run after its copy, per face.
void apply_outflow(Block& block, const Forest& forest, const GridConfig& config, const VariableRegistry& vars,
                   std::span<const int> groups,
                   const std::map<int, std::vector<GridDriver::OutflowCondition>>& conditions = {});

}  // namespace remnant::grid
