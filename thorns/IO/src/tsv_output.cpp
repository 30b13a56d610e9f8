#include "tsv_output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "centre_value.hpp"
#include "remnant/tsv_file.hpp"
#include "variable_list.hpp"

namespace remnant::io {

namespace {
ReductionKind reduction_from(const std::string& name) {
  for (auto k : {ReductionKind::minimum, ReductionKind::maximum, ReductionKind::sum, ReductionKind::volume_integral,
                 ReductionKind::norm1, ReductionKind::norm2})
    if (name == to_string(k)) return k;
  throw RunError("unknown reduction '" + name + "'");
}

void write_header(std::ostream& f, const TsvSeries& s) {
  f << "# " << s.column << "\n# 1:iteration\t2:time\t3:value\n";
}
}  // namespace

std::vector<TsvSeries> plan_tsv_series(const Context& ctx, const std::vector<std::string>& variables,
                                       const std::vector<std::string>& reductions) {
  std::vector<TsvSeries> out;
  for (const auto& v : resolve_variables(ctx, "tsv_variables", variables)) {
    if (ctx.vars().group(v.group).centering != Centering::cell)
      throw InputError(ctx.params().origin("IO", "tsv_variables"),
                       "IO::tsv_variables: " + v.full + " is not cell-centred; reductions need cell-centred groups");
    for (const auto& r : reductions) {
      TsvSeries s{v.group, v.comp, ReductionKind::minimum, r == "centre", "", ""};
      if (!s.centre) s.kind = reduction_from(r);
      s.path = ctx.out_dir() + "/" + v.file + "." + r + ".tsv";
      s.column = v.full + " " + r;
      out.push_back(s);
    }
  }
  return out;
}

void start_tsv_files(const std::vector<TsvSeries>& series, const Context& ctx) {
  if (ctx.rank() != 0) return;
  for (const auto& s : series) {
    std::ofstream f(s.path, std::ios::trunc);
    if (!f) throw RunError("cannot create " + s.path);
    write_header(f, s);
  }
}

void resume_tsv_files(const std::vector<TsvSeries>& series, const Context& ctx, std::int64_t iteration) {
  if (ctx.rank() != 0) return;
  std::int64_t dropped = 0;
  for (const auto& s : series) {
    if (!std::filesystem::exists(s.path)) {
      std::ofstream f(s.path);
      if (!f) throw RunError("cannot create " + s.path);
      write_header(f, s);
      continue;
    }
    dropped += trim_tsv_file(s.path, iteration);
  }
  if (dropped > 0)
    ctx.info("dropped " + std::to_string(dropped) + " TSV rows after the recovered iteration " + std::to_string(iteration));
}

void append_tsv_lines(std::vector<TsvSeries>& series, Context& ctx, const std::array<double, 3>& centre) {
  for (auto& s : series) {
    const double v = s.centre ? value_at_point(ctx.grid(), s.group, s.comp, centre) : ctx.grid().reduce(s.group, s.comp, s.kind);
    if (ctx.rank() != 0) continue;
    if (std::isnan(v) && s.nan_rows++ == 0)
      ctx.warn(s.path + ": NaN at iteration " + std::to_string(ctx.iteration()) +
               " (further NaN rows of this file are counted and reported at the end)");
    std::FILE* f = std::fopen(s.path.c_str(), "a");
    if (!f) throw RunError("cannot append to " + s.path);
    std::fprintf(f, "%lld\t%.17g\t%.17g\n", static_cast<long long>(ctx.iteration()), ctx.time(), v);
    if (std::fclose(f) != 0) throw RunError("cannot write " + s.path + " (disk full?)");
  }
}

}  // namespace remnant::io
