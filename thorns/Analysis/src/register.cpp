// Analysis_Star: diagnostics every Analysis::every iterations, appended to <out_dir>/analysis.tsv by rank 0.
#include <fstream>
#include <memory>

#include "Analysis/magnetic_diagnostics.hpp"
#include "Analysis/star_diagnostics.hpp"
#include "remnant/registrar.hpp"
#include "remnant/tsv_file.hpp"

namespace remnant::analysis {
namespace {

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
  }
  if (ctx.rank() == 0) {
    const std::string path = ctx.out_dir() + "/analysis.tsv";
    if (history.rows.empty()) start_or_resume_tsv_file(ctx, path, tsv_header(d.has_rotation, with_b));
    std::ofstream out(path, std::ios::app);
    out << tsv_line(d);
    if (!out) throw RunError("Analysis: cannot write " + path);
  }
  history.rows.push_back(d);
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
}
