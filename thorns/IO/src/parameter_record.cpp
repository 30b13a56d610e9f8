#include "parameter_record.hpp"

#include <map>
#include <sstream>

namespace remnant::io {

std::string parameter_record(const Context& ctx) {
  std::ostringstream out;
  std::vector<std::string> thorns{"Flesh"};
  thorns.insert(thorns.end(), ctx.active_thorns().begin(), ctx.active_thorns().end());
  for (const auto& t : thorns)
    for (const ParamSpec* s : ctx.params().specs_of(t))
      out << s->full_name() << '\t' << to_string(s->steerable) << '\t'
          << format_param_value(ctx.params().value(t, s->name)) << '\n';
  return out.str();
}

namespace {
struct Entry {
  std::string steerable, value;
};
std::map<std::string, Entry> parse(const std::string& record) {
  std::map<std::string, Entry> out;
  std::istringstream in(record);
  std::string line;
  while (std::getline(in, line)) {
    const auto a = line.find('\t');
    const auto b = a == std::string::npos ? a : line.find('\t', a + 1);
    if (b == std::string::npos) continue;
    out[line.substr(0, a)] = {line.substr(a + 1, b - a - 1), line.substr(b + 1)};
  }
  return out;
}
}  // namespace

ParameterChanges compare_parameters(const std::string& checkpoint_record, const std::string& current_record) {
  ParameterChanges c;
  const auto old = parse(checkpoint_record), now = parse(current_record);
  for (const auto& [name, e] : now) {
    const auto it = old.find(name);
    const std::string before = it == old.end() ? "(absent)" : it->second.value;
    if (before == e.value) continue;
    const std::string msg = name + ": checkpoint " + before + ", now " + e.value;
    if (e.steerable != "never") c.notes.push_back(msg);
    else if (name.rfind("Flesh::", 0) == 0) c.warnings.push_back(msg);
    else c.errors.push_back(msg);
  }
  return c;
}

}  // namespace remnant::io
