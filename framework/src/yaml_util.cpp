#include "yaml_util.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace remnant {

namespace {

std::string where_short(const YAML::Mark& m) { return std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1); }

// yaml-cpp keeps the last of two equal keys without a word: refuse them, in every map of the tree.
void refuse_duplicate_keys(const YAML::Node& node, const std::string& file) {
  if (node.IsMap()) {
    std::map<std::string, YAML::Mark> seen;
    for (const auto& kv : node) {
      if (kv.first.IsScalar()) {
        const auto [it, fresh] = seen.emplace(kv.first.Scalar(), kv.first.Mark());
        if (!fresh)
          throw InputError(location_of(file, kv.first), "duplicate key '" + kv.first.Scalar() + "' (first at line " +
                                                            where_short(it->second) +
                                                            "); YAML keeps only one of them: remove or merge the other");
      }
      refuse_duplicate_keys(kv.second, file);
    }
  } else if (node.IsSequence()) {
    for (const auto& e : node) refuse_duplicate_keys(e, file);
  }
}

}  // namespace

YAML::Node parse_yaml_text(const std::string& text, const std::string& file) {
  std::vector<YAML::Node> docs;
  try {
    docs = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    throw InputError(location_of(file, e.mark), "YAML syntax error: " + e.msg);
  }
  // A second '---' document would be ignored silently: refuse it (empty trailing documents are harmless).
  for (std::size_t i = 1; i < docs.size(); ++i)
    if (!docs[i].IsNull())
      throw InputError(location_of(file, docs[i]),
                       "a second YAML document (after '---'): a file holds one document; remove the '---' line "
                       "or merge the two parts");
  if (docs.empty()) return YAML::Node();
  refuse_duplicate_keys(docs[0], file);
  return docs[0];
}

YAML::Node load_yaml_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError({path, 0, 0}, "is a directory, not a YAML file");
  std::ifstream in(path);
  if (!in) throw InputError({path, 0, 0}, "cannot open file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_yaml_text(ss.str(), path);
}

static std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::vector<std::string> nearest_names(const std::string& word, const std::vector<std::string>& candidates,
                                       std::size_t max, bool any_distance) {
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const auto& c : candidates) scored.emplace_back(edit_distance(word, c), c);
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::string> out;
  // Only suggest names that are plausibly typos: within about a third of the word's length.
  const std::size_t limit = std::max<std::size_t>(2, (word.size() + 2) / 3);
  for (const auto& [d, c] : scored) {
    if (out.size() >= max) break;
    if (any_distance || d <= limit) out.push_back(c);
  }
  return out;
}

std::string join(const std::vector<std::string>& items, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) out += sep;
    out += items[i];
  }
  return out;
}

}  // namespace remnant
