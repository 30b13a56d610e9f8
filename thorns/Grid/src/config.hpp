#pragma once
// Turning Grid parameters into a UniformGridConfig and checking it.
#include <functional>
#include <string>

#include "Grid/uniform_grid.hpp"
#include "remnant/error.hpp"

namespace remnant {
class Parameters;
}

namespace remnant::grid {

// Where a setting came from, for error messages: the parfile location of Grid::<name>, or a
// description of the plain config.
using SettingLocator = std::function<SourceLocation(const std::string& name)>;

Boundary parse_boundary(const std::string& keyword, const SourceLocation& where);

// Throws InputError naming the offending setting(s). Returns the config with the entries beyond
// `dimension` normalised (one cell, one block, outflow) so that later code never looks at them.
UniformGridConfig checked(UniformGridConfig config, const SettingLocator& where);
UniformGridConfig checked(const UniformGridConfig& config);

UniformGridConfig config_from_parameters(const Parameters& params);

}  // namespace remnant::grid
