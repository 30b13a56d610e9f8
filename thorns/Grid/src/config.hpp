#pragma once
// Turning Grid parameters into a GridConfig and checking it: every bad layout is an InputError
// naming the parameter (and, from a parfile, its file:line:col).
#include <functional>
#include <string>

#include "Grid/grid_config.hpp"
#include "remnant/error.hpp"

namespace remnant {
class Parameters;
}

namespace remnant::grid {

// Where a setting came from, for error messages: the parfile location of Grid::<name>, or a
// description of the plain config.
using SettingLocator = std::function<SourceLocation(const std::string& name)>;

Boundary parse_boundary(const std::string& keyword, const SourceLocation& where);
CoordinateSystem parse_coordinates(const std::string& keyword, const SourceLocation& where);

// Throws InputError naming the offending setting(s). Returns the config with the entries beyond
// `dimension` normalised (one cell, one block, outflow, full angular range) so that later code
// never looks at them.
GridConfig checked(GridConfig config, const SettingLocator& where);
GridConfig checked(const GridConfig& config);

GridConfig config_from_parameters(const Parameters& params);

}  // namespace remnant::grid
