// Binds the Grid thorn to the flesh: it provides the mesh and regrids it.
#include <memory>

#include "Grid/amr_grid.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"

namespace remnant::grid {
namespace {

AmrGrid& amr(Context& ctx) {
  auto* g = dynamic_cast<AmrGrid*>(&ctx.grid());
  if (!g) throw RunError("Grid: the active grid is not the Grid thorn's");
  return *g;
}

void after_change(Context& ctx, const char* why) {
  ctx.invalidate_ghosts();
  ctx.info(std::string("Grid: ") + why + " at iteration " + std::to_string(ctx.iteration()) + ": " +
           std::to_string(ctx.grid().all_blocks().size()) + " blocks, " + std::to_string(amr(ctx).finest_level() + 1) +
           " levels");
  ctx.run_bin("post_regrid");
}

void regrid(Context& ctx) {
  if (amr(ctx).config().max_level == 0) return;
  if (amr(ctx).regrid()) after_change(ctx, "regrid");
}

// The initial adaptive passes: regrid on the initial data, then compute the initial data again
// on the new mesh (rather than keep prolonged values), until the mesh settles.
void initial_regrid(Context& ctx) {
  AmrGrid& g = amr(ctx);
  if (g.config().max_level == 0) return;
  auto passes = ctx.param<std::int64_t>("Grid", "initial_regrid_passes");
  if (passes < 0) passes = g.config().max_level;
  for (std::int64_t p = 0; p < passes; ++p) {
    if (!g.regrid()) break;
    ctx.invalidate_ghosts();
    ctx.run_bin("initial");
    after_change(ctx, "initial regrid");
  }
}

}  // namespace
}  // namespace remnant::grid

REMNANT_REGISTER_THORN(Grid) {
  using namespace remnant::grid;
  reg.grid_factory([](const remnant::GridSetup& setup) -> std::unique_ptr<remnant::GridDriver> {
    return std::make_unique<AmrGrid>(setup);
  });
  reg.function("Grid_Regrid", regrid);
  reg.function("Grid_InitialRegrid", initial_regrid);
}
