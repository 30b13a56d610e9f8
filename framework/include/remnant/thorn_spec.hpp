#pragma once
// thorn.yaml, parsed and schema-checked. One file per thorn is the single source of truth for its
// variables, parameters and scheduled functions (DESIGN.md section 3).
#include <string>
#include <vector>

#include "remnant/condition.hpp"
#include "remnant/error.hpp"
#include "remnant/parameters.hpp"
#include "remnant/variables.hpp"

namespace remnant {

enum class Region { interior, everywhere };

struct VariableAccess {
  std::string group;       // as written: "wave", "Thorn::group", or "@evolved" / "@rhs"
  Region region = Region::interior;
  SourceLocation where;
};

struct OrderingRef {
  std::string name;        // function or group name
  bool optional = false;   // no error when the target is not scheduled
  SourceLocation where;
};

// `if:` condition on a parameter: "Thorn::p" (bool true), "!Thorn::p", "Thorn::p == v", "!=".
struct ScheduleItem {
  std::string thorn;
  bool is_group = false;
  std::string name;             // function or group name
  std::string in;               // bin or group
  bool in_optional = false;     // `in: {name: G, optional: true}`: dropped when no active thorn
                                // schedules the group G (a hook of an optional thorn)
  std::vector<OrderingRef> before, after;
  std::vector<VariableAccess> reads, writes;
  int every = 1;                // run every N iterations (bins inside the evolution loop)
  std::string every_thorn, every_param;  // or every Thorn::param iterations (an int; <= 0: never)
  Condition condition;
  std::string repeat_while;     // groups only: predicate registered by the thorn
  std::string description;
  SourceLocation where;
};

struct ThornSpec {
  std::string name;
  std::string yaml_path;
  std::string description;
  std::vector<std::string> provides, requirements;
  std::vector<VariableGroupSpec> variables;  // ids unset
  std::vector<ParamSpec> parameters;
  std::vector<ScheduleItem> schedule;
};

// Parses and checks a thorn.yaml text; errors name yaml_path:line:col.
ThornSpec parse_thorn_spec(const std::string& yaml_text, const std::string& yaml_path);

// Adds the thorn's variable groups to the registry once the parfile is applied: a group whose
// `if:` is false gets no storage (recorded with add_without_storage). Storage conditions must
// name a parameter with 'steerable: never' (InputError at the group's line otherwise).
void register_variable_groups(const ThornSpec& spec, const Parameters& params, VariableRegistry& vars);

const std::vector<std::string>& standard_bins();
bool is_standard_bin(const std::string& name);

}  // namespace remnant
