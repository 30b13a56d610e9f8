// Analysis_Star: diagnostics every Analysis::every iterations, appended to <out_dir>/analysis.tsv by rank 0.
#include <cmath>
#include <fstream>
#include <memory>

#include "Analysis/magnetic_diagnostics.hpp"
#include "Analysis/rotation_magnetic.hpp"
#include "Analysis/star_diagnostics.hpp"
#include "Analysis/collision_reference.hpp"
#include "remnant/registrar.hpp"
#include "remnant/tsv_file.hpp"

namespace remnant::analysis {
namespace {

// The collision columns: rho_max and its point value normalised by the first row's, and h+ from the change of the
// momentum moment since the previous row. After a recovery both rows come from the resumed analysis.tsv
// (history.resumed); without it (no earlier rows found) the first row has neither: 1 and 0.
void add_collision_columns(Context& ctx, const History& history, StarDiagnostics& d) {
  d.collision = true;
  d.col = collision_diagnostics(ctx);
  if (history.resumed) {
    d.rho_max_norm = d.rho_max / history.resumed->rho_max;
    d.rho_max_point_norm = d.col.rho_max_point / history.resumed->rho_max_point;
  } else {
    d.rho_max_norm = history.rows.empty() ? 1.0 : d.rho_max / history.rows.front().rho_max;
    d.rho_max_point_norm = history.rows.empty() ? 1.0 : d.col.rho_max_point / history.rows.front().col.rho_max_point;
  }
  bool has_previous = !history.rows.empty();
  double previous_time = 0, previous_quad_dI = 0;
  if (has_previous) {
    previous_time = history.rows.back().time;
    previous_quad_dI = history.rows.back().col.quad_dI;
  } else if (history.resumed && history.resumed->has_previous) {
    has_previous = true;
    previous_time = history.resumed->previous_time;
    previous_quad_dI = history.resumed->previous_quad_dI;
  }
  if (has_previous && d.time > previous_time) {
    const double s = std::sin(ctx.param<double>("Analysis", "gw_theta"));
    d.h_plus = s * s / ctx.param<double>("Analysis", "gw_distance") * (d.col.quad_dI - previous_quad_dI) / (d.time - previous_time);
  }
}

void magnetic(Context& ctx) {
  if (!ctx.has_service("Analysis::magnetic")) ctx.publish("Analysis::magnetic", std::make_shared<MagneticDiagnostics>());
  ctx.service<MagneticDiagnostics>("Analysis::magnetic") = magnetic_diagnostics(ctx);
}

void star(Context& ctx) {
  if (!ctx.has_service("Analysis::history")) ctx.publish("Analysis::history", std::make_shared<History>());
  auto& history = ctx.service<History>("Analysis::history");
  StarDiagnostics d = star_diagnostics(ctx);
  const bool with_b = magnetic_run(ctx);
  if (with_b) {
    // Analysis_Magnetic ran just before (same `every`, ordered before this function).
    const auto& m = ctx.service<MagneticDiagnostics>("Analysis::magnetic");
    if (m.iteration != d.iteration) throw RunError("Analysis: magnetic diagnostics missing for this iteration");
    d.magnetic = m;
    if (d.has_rotation) add_magnetic_terms(d.rotation, ctx.service<double>("Analysis::rotation_magnetic_now"), m.E_mag);
  }
  const bool collision = collision_diagnostics_enabled(ctx);
  const std::string path = ctx.out_dir() + "/analysis.tsv";
  if (history.rows.empty()) {
    if (ctx.rank() == 0) start_or_resume_tsv_file(ctx, path, tsv_header(d.has_rotation, with_b, collision));
    if (collision && ctx.recovered()) history.resumed = resumed_collision_reference(ctx, path);
  }
  if (collision) add_collision_columns(ctx, history, d);
  if (ctx.rank() == 0) {
    std::ofstream out(path, std::ios::app);
    out << tsv_line(d);
    if (!out) throw RunError("Analysis: cannot write " + path);
  }
  history.rows.push_back(d);
}

// Runs before Analysis_Star (magnetised runs): the field's Komar term for that row's rotation columns.
void rotation_magnetic(Context& ctx) {
  if (!ctx.has_service("Analysis::rotation_magnetic_now")) ctx.publish("Analysis::rotation_magnetic_now", std::make_shared<double>(0.0));
  ctx.service<double>("Analysis::rotation_magnetic_now") = magnetic_komar_stress(ctx);
}

// Runs before Analysis_Star on the same iterations; its values go into that row (star_diagnostics).
void rotation(Context& ctx) {
  if (!ctx.has_service("Analysis::rotation_now")) ctx.publish("Analysis::rotation_now", std::make_shared<RotationDiagnostics>());
  ctx.service<RotationDiagnostics>("Analysis::rotation_now") = rotation_diagnostics(ctx);
}

}  // namespace
}  // namespace remnant::analysis

REMNANT_REGISTER_THORN(Analysis) {
  reg.function("Analysis_Magnetic", remnant::analysis::magnetic);
  reg.function("Analysis_Star", remnant::analysis::star);
  reg.function("Analysis_Rotation", remnant::analysis::rotation);
  reg.function("Analysis_RotationMagnetic", remnant::analysis::rotation_magnetic);
}
