#pragma once
// YAML parfiles: `include:` layering, `active_thorns:`, one map per thorn, command-line overrides
// `Thorn::param=value` and `active_thorns=[...]` / `active_thorns+=[...]`. Every value keeps its location so that errors name file:line:col.
#include <yaml-cpp/yaml.h>

#include <map>
#include <string>
#include <vector>

#include "remnant/error.hpp"
#include "remnant/parameters.hpp"

namespace remnant {

struct ParfileSetting {
  YAML::Node value;
  SourceLocation where;       // of the value
  SourceLocation key_where;   // of the key (for "unknown parameter" errors)
};

struct Parfile {
  std::vector<std::string> files;                    // the parfile and everything it includes
  std::vector<std::string> active_thorns;            // in order of first appearance
  std::map<std::string, SourceLocation> active_where;
  SourceLocation active_thorns_where;                // where active_thorns was (last) given
  // thorn -> parameter -> setting; insertion order is not needed (reported by name)
  std::map<std::string, std::map<std::string, ParfileSetting>> settings;
  std::map<std::string, SourceLocation> section_where;  // thorn section keys

  // Reads a parfile (from disk, or from `text` when given) with its includes.
  static Parfile load(const std::string& path, const std::string* text = nullptr);
  // Applies "Thorn::param=value", or "active_thorns=[...]" (replaces the list) /
  // "active_thorns+=[...]" (adds to it); `argument_index` is for error messages.
  void apply_override(const std::string& arg, int argument_index);
};

// True for the command-line forms "active_thorns=..." and "active_thorns+=...".
bool is_active_thorns_override(const std::string& arg);

// Checks every setting against the declared parameters and stores it: unknown thorns, inactive
// thorns, unknown parameters (with the nearest valid names), wrong types and ranges are errors.
void apply_parfile(const Parfile& pf, const std::vector<std::string>& compiled_thorns,
                   const std::vector<std::string>& active_thorns, Parameters& params);

}  // namespace remnant
