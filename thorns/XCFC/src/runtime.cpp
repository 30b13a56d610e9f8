#include "runtime.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "grid_bridge.hpp"

namespace remnant::xcfc {
namespace {

bool same_layout(const CompositeLayout& a, const CompositeLayout& b) {
  return a.base.n == b.base.n && a.base.coordinates == b.base.coordinates && a.base.dimension == b.base.dimension &&
         a.base.lo == b.base.lo && a.base.dx == b.base.dx && a.patch_cells == b.patch_cells && a.patches == b.patches;
}

// A refined level whose blocks at the spherical origin do not span every theta (and phi in 3D): the
// composite V-cycle then converges slowly (README, "Refined grids"); returns the first such level
// or 0.
int level_ending_in_theta_at_origin(const CompositeLayout& lay) {
  const GridShape& b = lay.base;
  if (b.coordinates != CoordinateSystem::spherical || b.dimension < 2 || b.boundary[0][0] != Boundary::origin) return 0;
  // Cells of the (theta[, phi]) surface that level l + 1's patches at r = 0 cover, against all.
  const bool three = b.dimension == 3;
  for (std::size_t l = 0; l < lay.patches.size(); ++l) {
    long long covered = 0;
    for (const auto& c : lay.patches[l])
      if (c[0] == 0) covered += static_cast<long long>(lay.patch_cells[1]) * (three ? lay.patch_cells[2] : 1);
    const long long all = (static_cast<long long>(b.n[1]) << (l + 1)) * (three ? static_cast<long long>(b.n[2]) << (l + 1) : 1);
    if (covered > 0 && covered < all) return static_cast<int>(l) + 1;
  }
  return 0;
}

}  // namespace

Runtime& runtime(Context& ctx) {
  if (!ctx.has_service("XCFC::runtime")) ctx.publish("XCFC::runtime", std::make_shared<Runtime>());
  return ctx.service<Runtime>("XCFC::runtime");
}

XcfcSolver& solver(Context& ctx) {
  Runtime& rt = runtime(ctx);
  CompositeLayout lay = layout_of_grid(ctx);
  if (!rt.solver || !same_layout(lay, rt.layout)) {
    if (const int l = level_ending_in_theta_at_origin(lay); l > 0 && !rt.warned_theta)
      ctx.warn("XCFC: refinement level " + std::to_string(l) +
               " ends in theta (or phi) next to the spherical origin; the composite metric solve converges slowly there "
               "(refine all theta near the origin, e.g. with a Grid::regions sphere; thorns/XCFC/README.md)"),
          rt.warned_theta = true;
    rt.layout = lay;
    rt.update_A = {};  // of the old mesh
    // The base level's cycles are split between the ranks (its 3D levels also stored split with
    // XCFC::multigrid_storage = distributed); patches are relaxed by their owners.
    const MultigridStorage storage = ctx.param<std::string>("XCFC", "multigrid_storage") == "distributed"
                                         ? MultigridStorage::distributed
                                         : MultigridStorage::replicated;
    rt.solver = lay.patches.empty() ? std::make_unique<XcfcSolver>(lay.base, ctx.grid().comm(), storage)
                                    : std::make_unique<XcfcSolver>(lay, ctx.grid().comm(), storage);
  }
  return *rt.solver;
}

std::string save_persistent(const Runtime& rt) {
  char text[400];  // 13 fields: at most 6 x 24 (hexadecimal floats) + 7 x 20 characters and the spaces
  std::snprintf(text, sizeof text, "%lld %lld %a %a %d %a %lld %lld %a %a %d %lld %a", static_cast<long long>(rt.steps_since_solve),
                static_cast<long long>(rt.solves), rt.t_last, rt.t_before, rt.history, rt.t_earlier,
                static_cast<long long>(rt.updates), static_cast<long long>(rt.update_cycles), rt.t_solve_last,
                rt.t_solve_before, rt.solve_history, static_cast<long long>(rt.interval), rt.update_prediction);
  return text;
}

void restore_persistent(Runtime& rt, const std::string& text) {
  std::istringstream s(text);
  std::string t_last, t_before, t_earlier;
  s >> rt.steps_since_solve >> rt.solves >> t_last >> t_before >> rt.history >> t_earlier;
  if (!s)
    throw RunError("XCFC: the checkpoint's persistent state '" + text +
                   "' is not 'steps solves t_last t_before history t_earlier'");
  rt.t_last = std::strtod(t_last.c_str(), nullptr);
  rt.t_before = std::strtod(t_before.c_str(), nullptr);
  rt.t_earlier = std::strtod(t_earlier.c_str(), nullptr);
  // The updates between solves (XCFC::update_every) came later: a checkpoint without their fields
  // has none, and its last solves are those of the history.
  std::string t_solve_last, t_solve_before;
  if (s >> rt.updates >> rt.update_cycles >> t_solve_last >> t_solve_before >> rt.solve_history) {
    rt.t_solve_last = std::strtod(t_solve_last.c_str(), nullptr);
    rt.t_solve_before = std::strtod(t_solve_before.c_str(), nullptr);
    // The adaptive interval (XCFC::cadence_tolerance) and the updates' largest prediction error
    // came later still: 0 starts them afresh.
    std::string update_prediction;
    if (!(s >> rt.interval >> update_prediction)) rt.interval = 0, update_prediction = "0";
    rt.update_prediction = std::strtod(update_prediction.c_str(), nullptr);
    return;
  }
  rt.updates = rt.update_cycles = 0, rt.interval = 0, rt.update_prediction = 0;
  rt.t_solve_last = rt.t_last, rt.t_solve_before = rt.t_before, rt.solve_history = std::min(rt.history, 2);
}

}  // namespace remnant::xcfc
