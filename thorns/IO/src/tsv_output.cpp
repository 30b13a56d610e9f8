#include "tsv_output.hpp"

#include <cstdio>
#include <fstream>

namespace remnant::io {

namespace {
ReductionKind reduction_from(const std::string& name) {
  for (auto k : {ReductionKind::minimum, ReductionKind::maximum, ReductionKind::sum, ReductionKind::volume_integral,
                 ReductionKind::norm1, ReductionKind::norm2})
    if (name == to_string(k)) return k;
  throw RunError("unknown reduction '" + name + "'");
}
}  // namespace

std::vector<TsvSeries> plan_tsv_series(const Context& ctx, const std::vector<std::string>& variables,
                                       const std::vector<std::string>& reductions) {
  std::vector<TsvSeries> out;
  const SourceLocation& where = ctx.params().origin("IO", "tsv_variables");
  for (const auto& v : variables) {
    const auto dot = v.find('.');
    const std::string group_name = v.substr(0, dot);
    const int g = ctx.vars().find(group_name);
    if (g < 0 || group_name.find("::") == std::string::npos) {
      std::vector<std::string> names;
      for (const auto& spec : ctx.vars().groups()) names.push_back(spec.full_name());
      std::string all;
      for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
      throw InputError(where, "IO::tsv_variables: '" + v + "' is not a variable group of an active thorn; groups: " + all);
    }
    const auto& spec = ctx.vars().group(g);
    for (int c = 0; c < spec.ncomp(); ++c) {
      if (dot != std::string::npos && spec.components[static_cast<std::size_t>(c)].name != v.substr(dot + 1)) continue;
      for (const auto& r : reductions) {
        TsvSeries s{g, c, reduction_from(r), "", ""};
        const std::string base = spec.thorn + "-" + spec.name + "." + spec.components[static_cast<std::size_t>(c)].name;
        s.path = ctx.out_dir() + "/" + base + "." + r + ".tsv";
        s.column = spec.full_name() + "." + spec.components[static_cast<std::size_t>(c)].name + " " + r;
        out.push_back(s);
      }
    }
    if (dot != std::string::npos && (out.empty() || out.back().group != g))
      throw InputError(where, "IO::tsv_variables: group " + spec.full_name() + " has no component '" + v.substr(dot + 1) + "'");
  }
  return out;
}

void start_tsv_files(const std::vector<TsvSeries>& series, const Context& ctx) {
  if (ctx.rank() != 0) return;
  for (const auto& s : series) {
    std::ofstream f(s.path, std::ios::trunc);
    if (!f) throw RunError("cannot create " + s.path);
    f << "# " << s.column << "\n# 1:iteration\t2:time\t3:value\n";
  }
}

void append_tsv_lines(const std::vector<TsvSeries>& series, Context& ctx) {
  for (const auto& s : series) {
    const double v = ctx.grid().reduce(s.group, s.comp, s.kind);
    if (ctx.rank() != 0) continue;
    std::FILE* f = std::fopen(s.path.c_str(), "a");
    if (!f) throw RunError("cannot append to " + s.path);
    std::fprintf(f, "%lld\t%.17g\t%.17g\n", static_cast<long long>(ctx.iteration()), ctx.time(), v);
    std::fclose(f);
  }
}

}  // namespace remnant::io
