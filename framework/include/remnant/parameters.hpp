#pragma once
// Typed, ranged, described parameters declared in thorn.yaml and set from parfiles.
// Thorns read them through references obtained once (Parameters::get), never by string in loops.
#include <cstdint>
#include <map>
#include <optional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "remnant/error.hpp"

namespace YAML { class Node; }

namespace remnant {

enum class ParamType { integer, real, boolean, keyword, string };
enum class Steerable { never, recover, always };
const char* to_string(ParamType t);
const char* to_string(Steerable s);

// An interval such as "(0:1]", "[1:*)", "[0:)"; '*' or an empty end is unbounded.
struct ParamRange {
  double lo = 0, hi = 0;
  bool lo_open = true, hi_open = true;
  bool lo_unbounded = true, hi_unbounded = true;
  std::string text;
  bool contains(double v) const;
  static ParamRange parse(const std::string& text, const SourceLocation& where);
};

using ParamValue = std::variant<std::int64_t, double, bool, std::string, std::vector<std::int64_t>,
                                std::vector<double>, std::vector<bool>, std::vector<std::string>>;

struct ParamSpec {
  std::string thorn;
  std::string name;
  ParamType type = ParamType::real;
  bool is_array = false;
  int length = -1;                      // required array length; -1 for any
  std::optional<ParamRange> range;      // integer and real (each element for arrays)
  std::vector<std::string> keywords;    // allowed values of a keyword
  ParamValue default_value;
  Steerable steerable = Steerable::never;
  std::string description;
  SourceLocation where;

  std::string full_name() const { return thorn + "::" + name; }
  std::string type_name() const;        // "real", "int[3]", "keyword", ...
  std::string allowed() const;          // "(0:1]", "one of: hll, hllc", "true or false", ...
};

// Parses and checks a YAML value against a spec; throws InputError naming `where` otherwise.
ParamValue parse_param_value(const ParamSpec& spec, const YAML::Node& node, const SourceLocation& where);
std::string format_param_value(const ParamValue& v);
// A number as the start-up checks' messages show it ("X = 1.5 needs ..."): printf's %.<digits>g
// (6: as parfiles write them; 17: every bit, where two values must match exactly). The message's
// location comes from Parameters::user_origin.
std::string format_number(double x, int significant_digits = 6);

class Parameters {
 public:
  void declare(ParamSpec spec);  // throws InputError on a duplicate
  const ParamSpec* find(std::string_view thorn, std::string_view name) const;
  void set(std::string_view thorn, std::string_view name, ParamValue v, const SourceLocation& where);
  const ParamValue& value(std::string_view thorn, std::string_view name) const;
  // Where the current value came from (the parfile location, or the thorn.yaml default).
  const SourceLocation& origin(std::string_view thorn, std::string_view name) const;
  // Where the user set the first of these parameters (the command line first, then the parfile):
  // the location an error about their combination should name. Falls back to the first one's origin.
  const SourceLocation& user_origin(std::initializer_list<std::pair<const char*, const char*>> names) const;

  // Typed access; T is std::int64_t, double, bool, std::string or a std::vector of them
  // (keywords are std::string). The reference stays valid for the life of the Parameters.
  template <class T>
  const T& get(std::string_view thorn, std::string_view name) const {
    const ParamValue& v = value(thorn, name);
    if (const T* p = std::get_if<T>(&v)) return *p;
    throw_type_mismatch(thorn, name);
  }

  std::vector<const ParamSpec*> specs_of(std::string_view thorn) const;
  std::vector<std::string> names_of(std::string_view thorn) const;
  // The resolved parameters of these thorns as a YAML map, one section per thorn.
  std::string to_yaml(const std::vector<std::string>& thorns) const;

 private:
  [[noreturn]] void throw_type_mismatch(std::string_view thorn, std::string_view name) const;
  struct Entry {
    ParamSpec spec;
    ParamValue value;
    SourceLocation origin;
  };
  static std::string key(std::string_view thorn, std::string_view name);
  std::map<std::string, Entry, std::less<>> entries_;
};

}  // namespace remnant
