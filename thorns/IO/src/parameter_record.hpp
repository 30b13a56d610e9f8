#pragma once
// The parameters as a checkpoint stores them ("Thorn::name<TAB>steerable<TAB>value" lines), and
// the recovery rule: a parameter with `steerable: never` must not change (the run would not be a
// continuation), except the Flesh's own (output directory, progress, debug, timers), which only
// warn; `recover`/`always` parameters may change and are listed.
#include <string>
#include <vector>

#include "remnant/context.hpp"

namespace remnant::io {

std::string parameter_record(const Context& ctx);

struct ParameterChanges {
  std::vector<std::string> errors;    // steerable: never (not Flesh)
  std::vector<std::string> warnings;  // Flesh parameters with steerable: never
  std::vector<std::string> notes;     // steerable: recover / always
};

ParameterChanges compare_parameters(const std::string& checkpoint_record, const std::string& current_record);

}  // namespace remnant::io
