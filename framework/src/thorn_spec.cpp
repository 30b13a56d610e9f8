#include "remnant/thorn_spec.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

#include "yaml_util.hpp"

namespace remnant {

const std::vector<std::string>& standard_bins() {
  static const std::vector<std::string> bins = {
      "startup", "paramcheck", "initial", "postinitial", "prestep", "evol",       "poststep",
      "analysis", "checkpoint", "terminate", "post_regrid", "post_recover"};
  return bins;
}

bool is_standard_bin(const std::string& name) {
  const auto& b = standard_bins();
  return std::find(b.begin(), b.end(), name) != b.end();
}

namespace {

struct Reader {
  std::string file;
  SourceLocation at(const YAML::Node& n) const { return location_of(file, n); }

  void check_keys(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what) const {
    if (!map.IsMap()) throw InputError(at(map), what + " must be a map");
    for (const auto& kv : map) {
      const std::string k = kv.first.as<std::string>();
      if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
        std::string msg = "unknown key '" + k + "' in " + what + "; allowed: " + join(allowed);
        auto near = nearest_names(k, allowed, 1);
        if (!near.empty()) msg += " (did you mean '" + near[0] + "'?)";
        throw InputError(at(kv.first), msg);
      }
    }
  }
  std::string str(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) throw InputError(at(n), what + " must be a string");
    return n.Scalar();
  }
  std::string required(const YAML::Node& map, const std::string& key, const std::string& what) const {
    if (!map[key]) throw InputError(at(map), what + " needs '" + key + "'");
    return str(map[key], what + "." + key);
  }
  std::vector<std::string> list(const YAML::Node& n, const std::string& what) const {
    std::vector<std::string> out;
    if (!n) return out;
    if (n.IsScalar()) return {n.Scalar()};
    if (!n.IsSequence()) throw InputError(at(n), what + " must be a list");
    for (const auto& e : n) out.push_back(str(e, what));
    return out;
  }
  bool boolean(const YAML::Node& n, const std::string& what) const {
    if (n.IsScalar() && (n.Scalar() == "true" || n.Scalar() == "false")) return n.Scalar() == "true";
    throw InputError(at(n), what + " must be true or false");
  }
  static bool is_identifier(const std::string& s) {
    static const std::regex re("[A-Za-z_][A-Za-z0-9_]*");
    return std::regex_match(s, re);
  }
  std::string identifier(const YAML::Node& n, const std::string& what) const {
    std::string s = str(n, what);
    if (!is_identifier(s)) throw InputError(at(n), what + " '" + s + "' is not a valid name (letters, digits, _)");
    return s;
  }

  // `ghosts: N` (0..8): fewer ghost layers than the Grid's. Evolved groups need the Grid's (their
  // ghosts are synchronised).
  int ghost_layers(const YAML::Node& n, const VariableGroupSpec& g) const {
    const std::string s = n.IsScalar() ? n.Scalar() : "<not a number>";
    static const std::regex digits("[0-8]");
    if (!std::regex_match(s, digits))
      throw InputError(at(n), "ghosts '" + s + "' of group '" + g.name + "' is not an integer from 0 to 8");
    const int v = s[0] - '0';
    if (g.role == VariableRole::evolved)
      throw InputError(at(n), "evolved group '" + g.name + "' cannot declare 'ghosts': MoL's groups keep the Grid's ghost zones");
    return v;
  }

  VariableGroupSpec variable(const YAML::Node& n, const std::string& thorn) const {
    check_keys(n, {"group", "centering", "tensor", "basis", "role", "rhs", "checkpoint", "prolongation", "ghosts", "if",
                "description"},
               "a variable group");
    VariableGroupSpec g;
    g.thorn = thorn;
    g.where = at(n);
    if (!n["group"]) throw InputError(at(n), "a variable group needs 'group: <name>'");
    g.name = identifier(n["group"], "group");
    static const std::vector<std::string> centerings = {"cell",   "face_x", "face_y", "face_z",
                                                        "edge_x", "edge_y", "edge_z", "vertex"};
    const std::string c = n["centering"] ? str(n["centering"], "centering") : "cell";
    auto ci = std::find(centerings.begin(), centerings.end(), c);
    if (ci == centerings.end())
      throw InputError(at(n["centering"]), "centering '" + c + "' is not one of: " + join(centerings));
    g.centering = static_cast<Centering>(ci - centerings.begin());
    if (!n["tensor"]) throw InputError(at(n), "variable group '" + g.name + "' needs 'tensor: [scalar u, vector v, ...]'");
    static const std::vector<std::string> kinds = {"scalar",       "vector",    "covector",
                                                   "axial_vector", "tensor_uu", "tensor_dd"};
    std::set<std::string> seen;
    for (const auto& e : n["tensor"].IsSequence() ? n["tensor"] : YAML::Node(YAML::NodeType::Sequence)) {
      const std::string entry = str(e, "tensor entry");
      std::istringstream is(entry);
      std::string kind, base, extra;
      is >> kind >> base >> extra;
      auto ki = std::find(kinds.begin(), kinds.end(), kind);
      // '<kind> <name>[N]': only component N (1..3) of a vector, covector or axial vector, e.g. the
      // face field of one direction, with that component's parities.
      int only = -1;
      static const std::regex one_component("([A-Za-z_][A-Za-z0-9_]*)\\[([123])\\]");
      std::smatch m;
      if (std::regex_match(base, m, one_component) && ki != kinds.end() && component_count(static_cast<TensorKind>(ki - kinds.begin())) == 3) {
        only = m[2].str()[0] - '1';
        base = m[1].str();
      }
      if (ki == kinds.end() || base.empty() || !extra.empty() || !is_identifier(base))
        throw InputError(at(e), "tensor entry '" + entry + "' must be '<kind> <name>' (or '<kind> <name>[N]' for one component of a vector) with kind one of: " + join(kinds));
      auto comps = expand_tensor(static_cast<TensorKind>(ki - kinds.begin()), base);
      if (only >= 0) comps = {comps[static_cast<std::size_t>(only)]};
      for (auto& comp : comps) {
        if (!seen.insert(comp.name).second)
          throw InputError(at(e), "component '" + comp.name + "' appears twice in group '" + g.name + "'");
        g.components.push_back(std::move(comp));
      }
    }
    if (g.components.empty()) throw InputError(at(n["tensor"]), "'tensor' must be a non-empty list");
    static const std::vector<std::string> roles = {"evolved", "derived", "auxiliary"};
    const std::string r = n["role"] ? str(n["role"], "role") : "auxiliary";
    auto ri = std::find(roles.begin(), roles.end(), r);
    if (ri == roles.end()) throw InputError(at(n["role"]), "role '" + r + "' is not one of: " + join(roles));
    g.role = static_cast<VariableRole>(ri - roles.begin());
    if (n["rhs"]) g.rhs = identifier(n["rhs"], "rhs");
    if (g.role == VariableRole::evolved && g.rhs.empty())
      throw InputError(at(n), "evolved group '" + g.name + "' needs 'rhs: <group>' so that MoL can integrate it");
    if (g.role != VariableRole::evolved && !g.rhs.empty())
      throw InputError(at(n["rhs"]), "only 'role: evolved' groups have an 'rhs'");
    g.checkpoint = n["checkpoint"] ? boolean(n["checkpoint"], "checkpoint") : g.role == VariableRole::evolved;
    if (n["prolongation"]) {
      static const std::vector<std::string> prolongations = {"conservative_linear", "linear", "none",
                                                             "divergence_preserving"};
      g.prolongation = str(n["prolongation"], "prolongation");
      if (std::find(prolongations.begin(), prolongations.end(), g.prolongation) == prolongations.end())
        throw InputError(at(n["prolongation"]), "prolongation '" + g.prolongation + "' is not one of: " + join(prolongations));
    }
    if (n["ghosts"]) g.ghosts = ghost_layers(n["ghosts"], g);
    if (n["basis"]) {
      const std::string b = str(n["basis"], "basis");
      if (b != "coordinate" && b != "cartesian")
        throw InputError(at(n["basis"]), "basis '" + b + "' is not one of: coordinate, cartesian");
      g.cartesian_basis = b == "cartesian";
    }
    if (n["if"]) g.condition = condition(n["if"]);
    if (n["description"]) g.description = str(n["description"], "description");
    return g;
  }

  ParamSpec parameter(const YAML::Node& n, const std::string& thorn) const {
    check_keys(n, {"name", "type", "length", "range", "values", "default", "steerable", "description"},
               "a parameter");
    ParamSpec p;
    p.thorn = thorn;
    p.where = at(n);
    if (!n["name"]) throw InputError(at(n), "a parameter needs 'name'");
    p.name = identifier(n["name"], "parameter name");
    const std::string what = "parameter " + p.full_name();
    std::string type = required(n, "type", what);
    if (type.size() > 2 && type.substr(type.size() - 2) == "[]") {
      p.is_array = true;
      type = type.substr(0, type.size() - 2);
    }
    static const std::vector<std::string> types = {"int", "real", "bool", "keyword", "string"};
    auto ti = std::find(types.begin(), types.end(), type);
    if (ti == types.end())
      throw InputError(at(n["type"]), what + ": type '" + type + "' is not one of: " + join(types) +
                                          " (append [] for arrays)");
    p.type = static_cast<ParamType>(ti - types.begin());
    if (n["length"]) {
      if (!p.is_array) throw InputError(at(n["length"]), what + ": 'length' applies to array types only");
      try {
        p.length = n["length"].as<int>();
      } catch (const YAML::Exception&) {
        throw InputError(at(n["length"]), what + ": 'length' must be an integer");
      }
    }
    if (n["range"]) {
      if (p.type != ParamType::integer && p.type != ParamType::real)
        throw InputError(at(n["range"]), what + ": 'range' applies to int and real parameters only");
      p.range = ParamRange::parse(str(n["range"], "range"), at(n["range"]));
    }
    if (p.type == ParamType::keyword) {
      p.keywords = list(n["values"], what + ".values");
      if (p.keywords.empty()) throw InputError(at(n), what + ": a keyword needs 'values: [a, b, ...]'");
    } else if (n["values"]) {
      throw InputError(at(n["values"]), what + ": 'values' applies to keyword parameters only");
    }
    if (!n["default"]) throw InputError(at(n), what + " needs a 'default'");
    p.default_value = parse_param_value(p, n["default"], at(n["default"]));
    if (n["steerable"]) {
      const std::string s = str(n["steerable"], "steerable");
      if (s == "never") p.steerable = Steerable::never;
      else if (s == "recover") p.steerable = Steerable::recover;
      else if (s == "always") p.steerable = Steerable::always;
      else throw InputError(at(n["steerable"]), what + ": steerable '" + s + "' is not one of: never, recover, always");
    }
    if (!n["description"]) throw InputError(at(n), what + " needs a 'description'");
    p.description = str(n["description"], "description");
    return p;
  }

  std::vector<VariableAccess> accesses(const YAML::Node& n, const std::string& what) const {
    std::vector<VariableAccess> out;
    if (!n) return out;
    if (!n.IsSequence()) throw InputError(at(n), what + " must be a list such as [wave(everywhere), rhs(interior)]");
    static const std::regex re(R"(\s*(@?[A-Za-z_][A-Za-z0-9_]*(?:::[A-Za-z_][A-Za-z0-9_]*)?)\s*(?:\(\s*([a-z]+)\s*\))?\s*)");
    for (const auto& e : n) {
      const std::string s = str(e, what);
      std::smatch m;
      if (!std::regex_match(s, m, re))
        throw InputError(at(e), what + " entry '" + s + "' must be 'group', 'Thorn::group' or 'group(region)'");
      VariableAccess a;
      a.group = m[1];
      a.where = at(e);
      const std::string region = m[2];
      if (region.empty() || region == "interior") a.region = Region::interior;
      else if (region == "everywhere") a.region = Region::everywhere;
      else throw InputError(at(e), "region '" + region + "' is not one of: interior, everywhere");
      out.push_back(a);
    }
    return out;
  }

  std::vector<OrderingRef> ordering(const YAML::Node& n, const std::string& what) const {
    std::vector<OrderingRef> out;
    if (!n) return out;
    YAML::Node seq = n;
    if (n.IsScalar() || n.IsMap()) {
      seq = YAML::Node(YAML::NodeType::Sequence);
      seq.push_back(n);
    }
    for (const auto& e : seq) {
      OrderingRef r;
      r.where = at(e);
      if (e.IsMap()) {
        check_keys(e, {"name", "optional"}, what + " entry");
        r.name = identifier(e["name"], what);
        if (e["optional"]) r.optional = boolean(e["optional"], "optional");
      } else {
        r.name = identifier(e, what);
      }
      out.push_back(r);
    }
    return out;
  }

  Condition condition(const YAML::Node& n) const {
    Condition c;
    c.text = str(n, "if");
    static const std::regex re(R"(\s*(!?)\s*([A-Za-z_][A-Za-z0-9_]*)::([A-Za-z_][A-Za-z0-9_]*)\s*(?:(==|!=)\s*(\S.*?))?\s*)");
    std::smatch m;
    if (!std::regex_match(c.text, m, re))
      throw InputError(at(n), "condition '" + c.text + "' must be 'Thorn::param', '!Thorn::param', "
                              "'Thorn::param == value' or 'Thorn::param != value'");
    c.thorn = m[2];
    c.param = m[3];
    if (m[4].matched) {
      if (m[1].length()) throw InputError(at(n), "condition '" + c.text + "': use either '!' or a comparison");
      c.op = m[4] == "==" ? Condition::Op::equal : Condition::Op::not_equal;
      c.value = m[5];
    } else {
      c.op = m[1].length() ? Condition::Op::is_false : Condition::Op::is_true;
    }
    return c;
  }

  ScheduleItem schedule_item(const YAML::Node& n, const std::string& thorn) const {
    if (!n.IsMap()) throw InputError(at(n), "a schedule entry must be a map with 'function:' or 'group:'");
    ScheduleItem s;
    s.thorn = thorn;
    s.where = at(n);
    if (n["function"] && n["group"]) throw InputError(at(n), "a schedule entry has either 'function' or 'group', not both");
    if (n["function"]) {
      check_keys(n, {"function", "in", "before", "after", "reads", "writes", "every", "if", "description"},
                 "a scheduled function");
      s.name = identifier(n["function"], "function");
    } else if (n["group"]) {
      check_keys(n, {"group", "in", "before", "after", "every", "if", "repeat_while", "description"},
                 "a schedule group");
      s.is_group = true;
      s.name = identifier(n["group"], "group");
      if (n["repeat_while"]) s.repeat_while = identifier(n["repeat_while"], "repeat_while");
    } else {
      throw InputError(at(n), "a schedule entry needs 'function: <name>' or 'group: <name>'");
    }
    const std::string what = (s.is_group ? "group " : "function ") + s.name;
    if (n["in"] && n["in"].IsMap()) {  // {name: <group>, optional: true}
      check_keys(n["in"], {"name", "optional"}, what + ".in");
      s.in = required(n["in"], "name", what + ".in");
      if (n["in"]["optional"]) s.in_optional = boolean(n["in"]["optional"], "optional");
    } else {
      s.in = required(n, "in", what);
    }
    s.before = ordering(n["before"], what + ".before");
    s.after = ordering(n["after"], what + ".after");
    s.reads = accesses(n["reads"], what + ".reads");
    s.writes = accesses(n["writes"], what + ".writes");
    if (n["every"]) {
      static const std::regex param_re(R"(([A-Za-z_][A-Za-z0-9_]*)::([A-Za-z_][A-Za-z0-9_]*))");
      std::smatch m;
      const std::string text = n["every"].IsScalar() ? n["every"].Scalar() : "";
      if (std::regex_match(text, m, param_re)) {
        s.every_thorn = m[1];
        s.every_param = m[2];
      } else {
        try {
          s.every = n["every"].as<int>();
        } catch (const YAML::Exception&) {
          s.every = 0;
        }
        if (s.every < 1)
          throw InputError(at(n["every"]), what + ": 'every' must be an integer >= 1 or an int parameter Thorn::param");
      }
    }
    if (n["if"]) s.condition = condition(n["if"]);
    if (!n["description"]) throw InputError(at(n), what + " needs a 'description'");
    s.description = str(n["description"], "description");
    return s;
  }
};

}  // namespace

ThornSpec parse_thorn_spec(const std::string& text, const std::string& path) {
  Reader rd{path};
  YAML::Node root = parse_yaml_text(text, path);
  if (!root.IsMap()) throw InputError({path, 1, 1}, "thorn.yaml must be a YAML map");
  rd.check_keys(root, {"thorn", "description", "provides", "requires", "variables", "parameters", "schedule"},
                "thorn.yaml");
  ThornSpec t;
  t.yaml_path = path;
  if (!root["thorn"]) throw InputError({path, 1, 1}, "thorn.yaml needs 'thorn: <Name>'");
  t.name = rd.identifier(root["thorn"], "thorn");
  if (root["description"]) t.description = rd.str(root["description"], "description");
  t.provides = rd.list(root["provides"], "provides");
  t.requirements = rd.list(root["requires"], "requires");
  auto seq = [&](const char* key) {
    YAML::Node n = root[key];
    if (n && !n.IsSequence() && !n.IsNull()) throw InputError(rd.at(n), std::string("'") + key + "' must be a list");
    return n && n.IsSequence() ? n : YAML::Node(YAML::NodeType::Sequence);
  };
  for (const auto& v : seq("variables")) t.variables.push_back(rd.variable(v, t.name));
  // Evolving staggered data needs a grid that can prolong and exchange it: the capability
  // `staggered_grid` (provided by Grid), checked at configure time and at start-up.
  const bool staggered_ok = std::find(t.requirements.begin(), t.requirements.end(), "staggered_grid") != t.requirements.end();
  for (const auto& g : t.variables)
    if (g.role == VariableRole::evolved && g.centering != Centering::cell && !staggered_ok)
      throw InputError(g.where, "evolved " + std::string(to_string(g.centering)) + "-centred group '" + g.name +
                                    "' needs a grid for staggered variables: add 'staggered_grid' to 'requires'");
  std::set<std::string> names;
  for (const auto& p : seq("parameters")) {
    t.parameters.push_back(rd.parameter(p, t.name));
    if (!names.insert(t.parameters.back().name).second)
      throw InputError(t.parameters.back().where, "parameter '" + t.parameters.back().name + "' is declared twice");
  }
  std::set<std::string> items;
  for (const auto& s : seq("schedule")) {
    t.schedule.push_back(rd.schedule_item(s, t.name));
    if (!items.insert(t.schedule.back().name).second)
      throw InputError(t.schedule.back().where, "'" + t.schedule.back().name + "' is scheduled twice in " + t.name);
  }
  return t;
}

void register_variable_groups(const ThornSpec& spec, const Parameters& params, VariableRegistry& vars) {
  for (const auto& v : spec.variables) {
    if (!v.condition.empty() && condition_is_steerable(v.condition, params))
      throw InputError(v.where, "group '" + v.name + "' has storage 'if: " + v.condition.text +
                                    "', whose parameter is steerable; conditions of storage need 'steerable: never'");
    if (condition_holds_now(v.condition, params, v.where)) vars.add(v);
    else vars.add_without_storage(v);
  }
}

}  // namespace remnant
