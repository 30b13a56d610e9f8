#include "grid_output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "grid_file.hpp"
#include "provenance.hpp"
#include "xdmf.hpp"

namespace remnant::io {

namespace fs = std::filesystem;

std::string series_name(const std::string& output_keyword) { return "grid-" + output_keyword; }

bool grid_output_due(GridOutputPlan& plan, const Context& ctx) {
  bool due = plan.every > 0 && ctx.iteration() % plan.every == 0;
  if (plan.every_time > 0) {
    // Relative slack so that t = 3 * 0.1 counts as the third multiple.
    const auto index = static_cast<std::int64_t>(std::floor(ctx.time() / plan.every_time * (1 + 1e-12) + 1e-12));
    if (index > plan.last_time_index) {
      plan.last_time_index = index;
      due = true;
    }
  }
  return due && !plan.variables.empty();
}

void write_grid_outputs(const GridOutputPlan& plan, Context& ctx) {
  GridDriver& grid = ctx.grid();
  for (const auto& keyword : plan.outputs) {
    const double t0 = MPI_Wtime();
    GridFileSpec spec;
    spec.coordinates = grid.coordinates();
    spec.grid_dimension = grid.dimension();
    spec.cut = make_cut(keyword, grid.dimension(), plan.point);
    spec.iteration = ctx.iteration();
    spec.time = ctx.time();
    spec.provenance = provenance_of(ctx);
    spec.variables = plan.variables;
    const std::string series = series_name(keyword);
    char name[64];
    std::snprintf(name, sizeof name, "%s.it%08lld", series.c_str(), static_cast<long long>(ctx.iteration()));
    spec.path = ctx.out_dir() + "/" + name + ".h5";
    const auto patches = extract_patches(grid.local_blocks(), grid.dimension(), spec.cut, plan.variables);
    const GridFileSummary summary = write_grid_file(spec, patches, ctx.comm());
    const double t_h5 = MPI_Wtime() - t0;
    if (!summary.written) {
      if (ctx.rank() == 0) ctx.warn(keyword + ": no cell of the grid lies on the cut through IO::slice_point; nothing written");
      continue;
    }
    if (ctx.rank() != 0) continue;
    for (std::size_t v = 0; v < summary.nan_counts.size(); ++v)
      if (summary.nan_counts[v] > 0)
        ctx.warn(spec.path + ": " + plan.variables[v].full + " holds " + std::to_string(summary.nan_counts[v]) +
                 " NaN values (attribute nan_count)");
    if (plan.xdmf && spec.cut.axes.size() >= 2) {
      write_xdmf_document(ctx.out_dir() + "/" + name + ".xmf", xdmf_grid_element(spec, summary, std::string(name) + ".h5"), false);
      write_xdmf_series(ctx.out_dir(), series, ctx.iteration());
    }
    const double t_xdmf = MPI_Wtime() - t0 - t_h5;
    const double values = static_cast<double>(summary.bytes) / 8;
    char msg[320];
    std::snprintf(msg, sizeof msg, "%s: %.1f MB of data, HDF5 %.3f s (%.2f s/GB, %.1f ns per value), XDMF %.3f s",
                  spec.path.c_str(), static_cast<double>(summary.bytes) / 1e6, t_h5,
                  t_h5 / (static_cast<double>(summary.bytes) / 1e9), t_h5 / values * 1e9, t_xdmf);
    ctx.info(msg);
  }
}

void forget_grid_outputs_after(const GridOutputPlan& plan, const Context& ctx, std::int64_t iteration) {
  if (ctx.rank() != 0) return;
  std::error_code ec;
  if (!fs::is_directory(ctx.out_dir(), ec)) return;
  int removed = 0;
  for (const auto& keyword : plan.outputs) {
    const std::string series = series_name(keyword);
    bool any = false;
    std::vector<fs::path> stale;  // collected first: no removal while iterating the directory
    for (const auto& e : fs::directory_iterator(ctx.out_dir(), ec)) {
      const std::string f = e.path().filename().string();
      const std::int64_t it = std::max(iteration_of(f, series, "h5"), iteration_of(f, series, "xmf"));
      if (it > iteration) stale.push_back(e.path());
      any = any || iteration_of(f, series, "xmf") >= 0;
    }
    for (const auto& p : stale) {
      std::error_code ec2;
      removed += fs::remove(p, ec2) ? 1 : 0;
    }
    if (any && plan.xdmf) write_xdmf_series(ctx.out_dir(), series, iteration);
  }
  if (removed > 0)
    ctx.info("removed " + std::to_string(removed) + " grid output files written after the recovered iteration " +
             std::to_string(iteration));
}

}  // namespace remnant::io
