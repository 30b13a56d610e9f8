#include "remnant/parameters.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <sstream>

#include "yaml_util.hpp"

namespace remnant {

const char* to_string(ParamType t) {
  switch (t) {
    case ParamType::integer: return "int";
    case ParamType::real: return "real";
    case ParamType::boolean: return "bool";
    case ParamType::keyword: return "keyword";
    case ParamType::string: return "string";
  }
  return "?";
}

const char* to_string(Steerable s) {
  switch (s) {
    case Steerable::never: return "never";
    case Steerable::recover: return "recover";
    case Steerable::always: return "always";
  }
  return "?";
}

bool ParamRange::contains(double v) const {
  if (std::isnan(v)) return false;
  if (!lo_unbounded && (lo_open ? !(v > lo) : !(v >= lo))) return false;
  if (!hi_unbounded && (hi_open ? !(v < hi) : !(v <= hi))) return false;
  return true;
}

static std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

ParamRange ParamRange::parse(const std::string& text, const SourceLocation& where) {
  const std::string t = trim(text);
  const auto bad = [&]() {
    return InputError(where, "bad range '" + text +
                                 "': expected e.g. \"(0:1]\", \"[1:*)\" or \"[0:)\" (brackets include "
                                 "the end, parentheses exclude it, '*' or nothing is unbounded)");
  };
  if (t.size() < 3 || (t.front() != '[' && t.front() != '(') || (t.back() != ']' && t.back() != ')'))
    throw bad();
  const auto colon = t.find(':');
  if (colon == std::string::npos) throw bad();
  ParamRange r;
  r.text = t;
  r.lo_open = t.front() == '(';
  r.hi_open = t.back() == ')';
  const std::string lo = trim(t.substr(1, colon - 1));
  const std::string hi = trim(t.substr(colon + 1, t.size() - colon - 2));
  auto parse_end = [&](const std::string& s, double& v, bool& unbounded) {
    unbounded = s.empty() || s == "*";
    if (unbounded) return;
    try {
      std::size_t pos = 0;
      v = std::stod(s, &pos);
      if (pos != s.size()) throw bad();
    } catch (const std::logic_error&) {
      throw bad();
    }
  };
  parse_end(lo, r.lo, r.lo_unbounded);
  parse_end(hi, r.hi, r.hi_unbounded);
  if (!r.lo_unbounded && !r.hi_unbounded && r.lo > r.hi) throw bad();
  return r;
}

std::string ParamSpec::type_name() const {
  std::string t = to_string(type);
  if (is_array) t += length >= 0 ? "[" + std::to_string(length) + "]" : "[]";
  return t;
}

std::string ParamSpec::allowed() const {
  switch (type) {
    case ParamType::integer: return range ? "integer in " + range->text : "any integer";
    case ParamType::real: return range ? "real in " + range->text : "any real";
    case ParamType::boolean: return "true or false";
    case ParamType::keyword: return "one of: " + join(keywords);
    case ParamType::string: return "any string";
  }
  return "";
}

namespace {

std::string describe_node(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  return "nothing";
}

std::int64_t parse_int(const ParamSpec& s, const YAML::Node& n, const SourceLocation& where) {
  if (!n.IsScalar()) throw InputError(where, s.full_name() + " expects an integer, got " + describe_node(n));
  const std::string& text = n.Scalar();
  std::int64_t v = 0;
  try {
    std::size_t pos = 0;
    v = std::stoll(text, &pos);
    if (pos != text.size()) throw std::invalid_argument("trailing");
  } catch (const std::logic_error&) {
    throw InputError(where, s.full_name() + " expects an integer (" + s.allowed() + "), got '" + text + "'");
  }
  if (s.range && !s.range->contains(static_cast<double>(v)))
    throw InputError(where, s.full_name() + " = " + text + " is out of range: allowed " + s.allowed());
  return v;
}

double parse_real(const ParamSpec& s, const YAML::Node& n, const SourceLocation& where) {
  if (!n.IsScalar()) throw InputError(where, s.full_name() + " expects a real number, got " + describe_node(n));
  const std::string& text = n.Scalar();
  std::string lower;
  for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == ".nan" || lower == ".inf" || lower == "-.inf" || lower == "+.inf")
    throw InputError(where, s.full_name() + " must be finite, got '" + text + "'");
  double v = 0;
  try {
    std::size_t pos = 0;
    v = std::stod(text, &pos);
    if (pos != text.size()) throw std::invalid_argument("trailing");
  } catch (const std::logic_error&) {
    throw InputError(where, s.full_name() + " expects a real number (" + s.allowed() + "), got '" + text + "'");
  }
  if (!std::isfinite(v)) throw InputError(where, s.full_name() + " must be finite, got '" + text + "'");
  if (s.range && !s.range->contains(v))
    throw InputError(where, s.full_name() + " = " + text + " is out of range: allowed " + s.allowed());
  return v;
}

bool parse_bool(const ParamSpec& s, const YAML::Node& n, const SourceLocation& where) {
  if (n.IsScalar()) {
    const std::string& t = n.Scalar();
    if (t == "true" || t == "True" || t == "yes") return true;
    if (t == "false" || t == "False" || t == "no") return false;
  }
  throw InputError(where, s.full_name() + " expects true or false, got " + describe_node(n));
}

std::string parse_keyword(const ParamSpec& s, const YAML::Node& n, const SourceLocation& where) {
  if (!n.IsScalar()) throw InputError(where, s.full_name() + " expects " + s.allowed() + ", got " + describe_node(n));
  const std::string& t = n.Scalar();
  for (const auto& k : s.keywords)
    if (k == t) return t;
  std::string msg = s.full_name() + " = '" + t + "' is not allowed: " + s.allowed();
  auto near = nearest_names(t, s.keywords, 1);
  if (!near.empty()) msg += " (did you mean '" + near[0] + "'?)";
  throw InputError(where, msg);
}

std::string parse_string(const ParamSpec& s, const YAML::Node& n, const SourceLocation& where) {
  if (!n.IsScalar()) throw InputError(where, s.full_name() + " expects a string, got " + describe_node(n));
  return n.Scalar();
}

template <class T, class F>
std::vector<T> parse_array(const ParamSpec& s, const YAML::Node& n, const SourceLocation& where, F&& one) {
  if (!n.IsSequence())
    throw InputError(where, s.full_name() + " expects a list (" + s.type_name() + ", each " + s.allowed() +
                                "), got " + describe_node(n));
  if (s.length >= 0 && static_cast<int>(n.size()) != s.length)
    throw InputError(where, s.full_name() + " expects exactly " + std::to_string(s.length) +
                                " values, got " + std::to_string(n.size()));
  std::vector<T> out;
  for (const auto& e : n) out.push_back(one(s, e, e.Mark().line >= 0 ? location_of(where.file, e) : where));
  return out;
}

}  // namespace

ParamValue parse_param_value(const ParamSpec& s, const YAML::Node& n, const SourceLocation& where) {
  if (!s.is_array) {
    switch (s.type) {
      case ParamType::integer: return parse_int(s, n, where);
      case ParamType::real: return parse_real(s, n, where);
      case ParamType::boolean: return parse_bool(s, n, where);
      case ParamType::keyword: return parse_keyword(s, n, where);
      case ParamType::string: return parse_string(s, n, where);
    }
  }
  switch (s.type) {
    case ParamType::integer: return parse_array<std::int64_t>(s, n, where, parse_int);
    case ParamType::real: return parse_array<double>(s, n, where, parse_real);
    case ParamType::boolean: return parse_array<bool>(s, n, where, parse_bool);
    case ParamType::keyword: return parse_array<std::string>(s, n, where, parse_keyword);
    case ParamType::string: return parse_array<std::string>(s, n, where, parse_string);
  }
  throw InputError(where, "unknown parameter type");
}

namespace {
std::string format_real(double v) {
  // The shortest decimal form that reads back as the same double.
  std::string s;
  for (int digits = 15; digits <= 17; ++digits) {
    std::ostringstream os;
    os << std::setprecision(digits) << v;
    s = os.str();
    if (std::stod(s) == v) break;
  }
  // Keep reals recognisable as reals when written back to YAML.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}
std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}
}  // namespace

namespace {
template <class T>
std::string format_list(const std::vector<T>& x);
std::string format_one(std::int64_t x) { return std::to_string(x); }
std::string format_one(double x) { return format_real(x); }
std::string format_one(bool x) { return x ? "true" : "false"; }
std::string format_one(const std::string& x) { return quote(x); }
template <class T>
std::string format_list(const std::vector<T>& x) {
  std::vector<std::string> items;
  for (const auto& e : x) items.push_back(format_one(static_cast<T>(e)));
  return "[" + join(items) + "]";
}
}  // namespace

std::string format_param_value(const ParamValue& v) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, std::int64_t> || std::is_same_v<T, double> || std::is_same_v<T, bool> ||
                      std::is_same_v<T, std::string>)
          return format_one(x);
        else
          return format_list(x);
      },
      v);
}

std::string Parameters::key(std::string_view thorn, std::string_view name) {
  std::string k(thorn);
  k += "::";
  k += name;
  return k;
}

void Parameters::declare(ParamSpec spec) {
  std::string k = spec.full_name();
  if (auto it = entries_.find(k); it != entries_.end())
    throw InputError(spec.where, "parameter " + k + " is declared twice (first at " + it->second.spec.where.str() + ")");
  Entry e{spec, spec.default_value, spec.where};
  entries_.emplace(std::move(k), std::move(e));
}

const ParamSpec* Parameters::find(std::string_view thorn, std::string_view name) const {
  auto it = entries_.find(key(thorn, name));
  return it == entries_.end() ? nullptr : &it->second.spec;
}

void Parameters::set(std::string_view thorn, std::string_view name, ParamValue v, const SourceLocation& where) {
  auto it = entries_.find(key(thorn, name));
  if (it == entries_.end()) throw InputError(where, "unknown parameter " + key(thorn, name));
  if (v.index() != it->second.value.index())
    throw InputError(where, "parameter " + key(thorn, name) + " set with a value of the wrong type");
  it->second.value = std::move(v);
  it->second.origin = where;
}

const ParamValue& Parameters::value(std::string_view thorn, std::string_view name) const {
  auto it = entries_.find(key(thorn, name));
  if (it == entries_.end()) throw RunError("no parameter " + key(thorn, name) + " is declared");
  return it->second.value;
}

const SourceLocation& Parameters::origin(std::string_view thorn, std::string_view name) const {
  auto it = entries_.find(key(thorn, name));
  if (it == entries_.end()) throw RunError("no parameter " + key(thorn, name) + " is declared");
  return it->second.origin;
}

void Parameters::throw_type_mismatch(std::string_view thorn, std::string_view name) const {
  const ParamSpec* s = find(thorn, name);
  throw RunError("parameter " + key(thorn, name) + " is of type " + (s ? s->type_name() : "?") +
                 ": read it as std::int64_t (int), double (real), bool, std::string (keyword, string) "
                 "or a std::vector of those (arrays)");
}

std::vector<const ParamSpec*> Parameters::specs_of(std::string_view thorn) const {
  std::vector<const ParamSpec*> out;
  for (const auto& [k, e] : entries_)
    if (e.spec.thorn == thorn) out.push_back(&e.spec);
  return out;
}

std::vector<std::string> Parameters::names_of(std::string_view thorn) const {
  std::vector<std::string> out;
  for (const auto* s : specs_of(thorn)) out.push_back(s->name);
  return out;
}

std::string Parameters::to_yaml(const std::vector<std::string>& thorns) const {
  std::string out;
  for (const auto& t : thorns) {
    auto specs = specs_of(t);
    if (specs.empty()) continue;
    out += t + ":\n";
    for (const auto* s : specs) out += "  " + s->name + ": " + format_param_value(value(t, s->name)) + "\n";
  }
  return out;
}

std::string format_number(double x, int significant_digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, x);
  return buf;
}

const SourceLocation& Parameters::user_origin(std::initializer_list<std::pair<const char*, const char*>> names) const {
  for (const bool command_line : {true, false})
    for (const auto& [thorn, name] : names) {
      if (!find(thorn, name)) continue;
      const SourceLocation& where = origin(thorn, name);
      const bool is_default =
          where.file.find("thorn.yaml") != std::string::npos || where.file.find("flesh.yaml") != std::string::npos;
      if (!is_default && (!command_line || where.file.rfind("command line", 0) == 0)) return where;
    }
  const auto& [thorn, name] = *names.begin();
  return origin(thorn, name);
}

}  // namespace remnant
