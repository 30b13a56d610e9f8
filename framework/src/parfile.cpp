#include "remnant/parfile.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>
#include <set>

#include "yaml_util.hpp"

namespace remnant {

namespace fs = std::filesystem;

namespace {

void load_into(Parfile& pf, const std::string& path, const std::string* text, std::vector<std::string>& stack) {
  const std::string canonical = text ? path : fs::weakly_canonical(path).string();
  if (std::find(stack.begin(), stack.end(), canonical) != stack.end())
    throw InputError({path, 0, 0}, "include cycle: " + join(stack, " -> ") + " -> " + canonical);
  stack.push_back(canonical);
  YAML::Node root = text ? parse_yaml_text(*text, path) : load_yaml_file(path);
  pf.files.push_back(path);
  if (root.IsNull()) {
    stack.pop_back();
    return;
  }
  if (!root.IsMap())
    throw InputError(location_of(path, root), "a parfile must be a YAML map: include, active_thorns, then one map per thorn");
  // Includes first: this file's own settings override them.
  if (YAML::Node inc = root["include"]) {
    std::vector<YAML::Node> items;
    if (inc.IsScalar()) items.push_back(inc);
    else if (inc.IsSequence()) for (const auto& e : inc) items.push_back(e);
    else throw InputError(location_of(path, inc), "'include' must be a file name or a list of file names");
    for (const auto& e : items) {
      if (!e.IsScalar()) throw InputError(location_of(path, e), "'include' entries must be file names");
      fs::path p = e.Scalar();
      if (p.is_relative()) p = fs::path(path).parent_path() / p;
      if (!fs::exists(p)) throw InputError(location_of(path, e), "included parfile '" + p.string() + "' does not exist");
      if (fs::is_directory(p))
        throw InputError(location_of(path, e), "included parfile '" + p.string() + "' is a directory; include wants YAML files");
      load_into(pf, p.string(), nullptr, stack);
    }
  }
  for (const auto& kv : root) {
    const std::string key = kv.first.Scalar();
    const SourceLocation key_where = location_of(path, kv.first);
    if (key == "include") continue;
    if (key == "active_thorns") {
      if (!kv.second.IsSequence())
        throw InputError(location_of(path, kv.second), "'active_thorns' must be a list of thorn names");
      pf.active_thorns_where = key_where;
      std::map<std::string, SourceLocation> in_this_list;
      for (const auto& t : kv.second) {
        if (!t.IsScalar()) throw InputError(location_of(path, t), "'active_thorns' entries must be thorn names");
        // The same name twice in one list is a slip (an include may repeat thorns: lists are merged).
        if (const auto [first, fresh] = in_this_list.emplace(t.Scalar(), location_of(path, t)); !fresh)
          throw InputError(location_of(path, t), "thorn '" + t.Scalar() + "' is listed twice in active_thorns (first at " +
                                                     first->second.str() + ")");
        if (std::find(pf.active_thorns.begin(), pf.active_thorns.end(), t.Scalar()) == pf.active_thorns.end()) {
          pf.active_thorns.push_back(t.Scalar());
          pf.active_where[t.Scalar()] = location_of(path, t);
        }
      }
      continue;
    }
    if (kv.second.IsNull()) {
      pf.section_where[key] = key_where;
      continue;
    }
    if (!kv.second.IsMap())
      throw InputError(key_where, "'" + key + "' must be a map of parameters (thorn sections look like 'WaveToy: {amplitude: 1}')");
    pf.section_where[key] = key_where;
    auto& section = pf.settings[key];
    for (const auto& p : kv.second) {
      const std::string name = p.first.Scalar();
      section[name] = ParfileSetting{p.second, location_of(path, p.second), location_of(path, p.first)};
    }
  }
  stack.pop_back();
}

}  // namespace

Parfile Parfile::load(const std::string& path, const std::string* text) {
  Parfile pf;
  std::vector<std::string> stack;
  load_into(pf, path, text, stack);
  return pf;
}

namespace {
// "active_thorns=[A, B]" replaces the parfile's list; "active_thorns+=[C]" (or "+=C") adds to it.
void apply_active_thorns_override(Parfile& pf, const std::string& arg, const SourceLocation& where) {
  const bool add = arg.rfind("active_thorns+=", 0) == 0;
  const std::string text = arg.substr(add ? 15 : 14);
  YAML::Node parsed;
  try {
    parsed = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(where, "cannot parse the thorn list: " + e.msg);
  }
  // (yaml-cpp nodes have reference semantics: build a new sequence rather than assign into `parsed`)
  YAML::Node list(YAML::NodeType::Sequence);
  if (parsed.IsScalar() && add)
    list.push_back(parsed.Scalar());
  else
    list = parsed;
  if (!list.IsSequence() || list.size() == 0)
    throw InputError(where, add ? "expected active_thorns+=[Thorn, ...] (or active_thorns+=Thorn)"
                                : "expected active_thorns=[Thorn, ...], a non-empty list of thorn names");
  if (!add) {
    pf.active_thorns.clear();
    pf.active_where.clear();
  }
  for (const auto& t : list) {
    if (!t.IsScalar() || t.Scalar().empty()) throw InputError(where, "'active_thorns' entries must be thorn names");
    if (std::find(pf.active_thorns.begin(), pf.active_thorns.end(), t.Scalar()) != pf.active_thorns.end()) {
      if (add) continue;  // adding a thorn that is already active is harmless
      throw InputError(where, "thorn '" + t.Scalar() + "' is listed twice in active_thorns");
    }
    pf.active_thorns.push_back(t.Scalar());
    pf.active_where[t.Scalar()] = where;
  }
  pf.active_thorns_where = where;
}
}  // namespace

void Parfile::apply_override(const std::string& arg, int index) {
  const SourceLocation where{"command line argument " + std::to_string(index) + " '" + arg + "'", 0, 0};
  if (is_active_thorns_override(arg)) {
    apply_active_thorns_override(*this, arg, where);
    return;
  }
  static const std::regex re(R"(([A-Za-z_][A-Za-z0-9_]*)::([A-Za-z_][A-Za-z0-9_]*)=(.*))");
  std::smatch m;
  if (!std::regex_match(arg, m, re))
    throw InputError(where, "expected Thorn::parameter=value, active_thorns=[...] or active_thorns+=[...]");
  YAML::Node value;
  try {
    value = YAML::Load(m[3].str());
  } catch (const YAML::Exception& e) {
    throw InputError(where, "cannot parse the value: " + e.msg);
  }
  if (!value.IsDefined() || value.IsNull()) value = YAML::Node(m[3].str());
  settings[m[1]][m[2]] = ParfileSetting{value, where, where};
  section_where.emplace(m[1], where);
}

namespace {
std::vector<std::string> nearest_any(const std::string& word, const std::vector<std::string>& candidates) {
  // Always offer something for unknown parameters: the closest few by edit distance, typo or not.
  return nearest_names(word, candidates, 3, /*any_distance=*/true);
}
}  // namespace

void apply_parfile(const Parfile& pf, const std::vector<std::string>& compiled, const std::vector<std::string>& active,
                   Parameters& params) {
  for (const auto& [thorn, where] : pf.section_where) {
    const bool is_compiled = std::find(compiled.begin(), compiled.end(), thorn) != compiled.end();
    const bool is_active = std::find(active.begin(), active.end(), thorn) != active.end();
    if (!is_compiled) {
      std::string msg = "unknown thorn '" + thorn + "'";
      auto near = nearest_names(thorn, compiled, 3);
      if (!near.empty()) msg += " (did you mean " + join(near, ", ") + "?)";
      msg += "; thorns in this executable: " + join(compiled);
      throw InputError(where, msg);
    }
    if (!is_active)
      throw InputError(where, "parameters of thorn " + thorn + " are set, but " + thorn +
                                  " is not in active_thorns (active: " + join(active) + ")");
  }
  for (const auto& [thorn, section] : pf.settings) {
    for (const auto& [name, setting] : section) {
      const ParamSpec* spec = params.find(thorn, name);
      if (!spec) {
        std::vector<std::string> full;
        for (const auto& n : params.names_of(thorn)) full.push_back(thorn + "::" + n);
        auto near = nearest_any(name, params.names_of(thorn));
        for (auto& n : near) n = thorn + "::" + n;
        std::string msg = "unknown parameter " + thorn + "::" + name;
        if (full.empty()) msg += "; thorn " + thorn + " has no parameters";
        else msg += "; nearest valid names: " + join(near) + " (see `remnant --describe " + thorn + "`)";
        throw InputError(setting.key_where, msg);
      }
      params.set(thorn, name, parse_param_value(*spec, setting.value, setting.where), setting.where);
    }
  }
}

bool is_active_thorns_override(const std::string& arg) {
  return arg.rfind("active_thorns=", 0) == 0 || arg.rfind("active_thorns+=", 0) == 0;
}

}  // namespace remnant
