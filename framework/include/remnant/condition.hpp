#pragma once
// A condition on one parameter, `Thorn::param`, `!Thorn::param`, `Thorn::param == value` or
// `Thorn::param != value`: when a scheduled item runs (its `if:`) and whether a variable group has
// storage at all (a group's `if:`, evaluated once at start-up).
#include <string>

#include "remnant/error.hpp"

namespace remnant {

class Parameters;

struct Condition {
  std::string thorn, param;
  enum class Op { is_true, is_false, equal, not_equal } op = Op::is_true;
  std::string value;       // as YAML scalar text for equal/not_equal
  std::string text;
  bool empty() const { return param.empty(); }
};

// The condition's value with the parameters as they are now. Throws InputError at `where` when the
// parameter is unknown or a bare condition names a parameter that is not a bool.
bool condition_holds_now(const Condition& c, const Parameters& params, const SourceLocation& where);

// Whether the condition's parameter can change after start-up (steerable other than 'never').
bool condition_is_steerable(const Condition& c, const Parameters& params);

}  // namespace remnant
