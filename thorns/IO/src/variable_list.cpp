#include "variable_list.hpp"

namespace remnant::io {

std::vector<VariableRef> resolve_variables(const Context& ctx, const std::string& param,
                                           const std::vector<std::string>& names) {
  std::vector<VariableRef> out;
  const SourceLocation& where = ctx.params().origin("IO", param);
  for (const auto& v : names) {
    const auto dot = v.find('.');
    const std::string group_name = v.substr(0, dot);
    const int g = ctx.vars().find(group_name);
    if (g < 0 || group_name.find("::") == std::string::npos) {
      std::string all;
      for (const auto& spec : ctx.vars().groups()) all += (all.empty() ? "" : ", ") + spec.full_name();
      throw InputError(where, "IO::" + param + ": '" + v + "' is not a variable group of an active thorn; groups: " + all);
    }
    const auto& spec = ctx.vars().group(g);
    bool found = false;
    for (int c = 0; c < spec.ncomp(); ++c) {
      const std::string& comp = spec.components[static_cast<std::size_t>(c)].name;
      if (dot != std::string::npos && comp != v.substr(dot + 1)) continue;
      found = true;
      out.push_back({g, c, spec.full_name() + "." + comp, spec.thorn + "-" + spec.name + "." + comp});
    }
    if (!found) {
      std::string comps;
      for (const auto& c : spec.components) comps += (comps.empty() ? "" : ", ") + c.name;
      throw InputError(where, "IO::" + param + ": group " + spec.full_name() + " has no component '" + v.substr(dot + 1) +
                                  "'; components: " + comps);
    }
  }
  return out;
}

}  // namespace remnant::io
