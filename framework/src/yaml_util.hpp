#pragma once
// Loading YAML with locations that users can act on (file:line:col, 1-based).
#include <yaml-cpp/yaml.h>

#include <string>

#include "remnant/error.hpp"

namespace remnant {

inline SourceLocation location_of(const std::string& file, const YAML::Mark& m) {
  if (m.line < 0) return {file, 0, 0};
  return {file, m.line + 1, m.column + 1};
}
inline SourceLocation location_of(const std::string& file, const YAML::Node& n) {
  return location_of(file, n.Mark());
}

// Parses text; a syntax error becomes an InputError with line and column.
YAML::Node parse_yaml_text(const std::string& text, const std::string& file);
YAML::Node load_yaml_file(const std::string& path);

// "Did you mean ...": the candidates closest to `word` by edit distance (at most `max`).
std::vector<std::string> nearest_names(const std::string& word, const std::vector<std::string>& candidates,
                                       std::size_t max = 3, bool any_distance = false);
std::string join(const std::vector<std::string>& items, const std::string& sep = ", ");

}  // namespace remnant
