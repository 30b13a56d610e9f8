// Analysis_Star: diagnostics every Analysis::every iterations, appended to <out_dir>/analysis.tsv by rank 0.
#include <cmath>
#include <fstream>
#include <memory>

#include "Analysis/star_diagnostics.hpp"
#include "remnant/registrar.hpp"
#include "remnant/tsv_file.hpp"

namespace remnant::analysis {
namespace {

// The collision columns: rho_max normalised by the first row's, and h+ from the change of the
// momentum moment since the previous row (after a restart the first row has neither: 0 and 1).
void add_collision_columns(Context& ctx, const History& history, StarDiagnostics& d) {
  d.collision = true;
  d.col = collision_diagnostics(ctx);
  d.rho_max_norm = history.rows.empty() ? 1.0 : d.rho_max / history.rows.front().rho_max;
  if (!history.rows.empty() && d.time > history.rows.back().time) {
    const double s = std::sin(ctx.param<double>("Analysis", "gw_theta"));
    d.h_plus = s * s / ctx.param<double>("Analysis", "gw_distance") * (d.col.quad_dI - history.rows.back().col.quad_dI) /
               (d.time - history.rows.back().time);
  }
}

void star(Context& ctx) {
  if (!ctx.has_service("Analysis::history")) ctx.publish("Analysis::history", std::make_shared<History>());
  auto& history = ctx.service<History>("Analysis::history");
  StarDiagnostics d = star_diagnostics(ctx);
  if (collision_diagnostics_enabled(ctx)) add_collision_columns(ctx, history, d);
  if (ctx.rank() == 0) {
    const std::string path = ctx.out_dir() + "/analysis.tsv";
    if (history.rows.empty()) start_or_resume_tsv_file(ctx, path, tsv_header(d.collision));
    std::ofstream out(path, std::ios::app);
    out << tsv_line(d);
    if (!out) throw RunError("Analysis: cannot write " + path);
  }
  history.rows.push_back(d);
}

}  // namespace
}  // namespace remnant::analysis

REMNANT_REGISTER_THORN(Analysis) { reg.function("Analysis_Star", remnant::analysis::star); }
