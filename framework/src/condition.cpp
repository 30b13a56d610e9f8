#include "remnant/condition.hpp"

#include <yaml-cpp/yaml.h>

#include "remnant/parameters.hpp"

namespace remnant {

namespace {
const ParamSpec& spec_of(const Condition& c, const Parameters& params, const SourceLocation& where) {
  const ParamSpec* spec = params.find(c.thorn, c.param);
  if (!spec) throw InputError(where, "condition '" + c.text + "' names an unknown parameter (is thorn " + c.thorn + " active?)");
  return *spec;
}
}  // namespace

bool condition_holds_now(const Condition& c, const Parameters& params, const SourceLocation& where) {
  if (c.empty()) return true;
  const ParamSpec& spec = spec_of(c, params, where);
  const ParamValue& v = params.value(c.thorn, c.param);
  using Op = Condition::Op;
  if (c.op == Op::equal || c.op == Op::not_equal) {
    const ParamValue expected = parse_param_value(spec, YAML::Node(c.value), where);
    return (v == expected) == (c.op == Op::equal);
  }
  if (spec.type != ParamType::boolean || spec.is_array)
    throw InputError(where, "condition '" + c.text + "' needs a bool parameter; use == or != for " + spec.type_name());
  return std::get<bool>(v) == (c.op == Op::is_true);
}

bool condition_is_steerable(const Condition& c, const Parameters& params) {
  const ParamSpec* spec = params.find(c.thorn, c.param);
  return spec && spec->steerable != Steerable::never;
}

}  // namespace remnant
