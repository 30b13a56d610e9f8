// XCFC: binds the scheduled functions of thorn.yaml. The solve (solve_sequence), its cadence and
// the metric between solves (cadence), the per-simulation state (runtime) and the log (solve_log)
// live beside it.
#include <stdexcept>
#include <string>
#include <vector>

#include "cadence.hpp"
#include "grid_bridge.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "runtime.hpp"
#include "solve_sequence.hpp"

namespace remnant::xcfc {
namespace {

// Before anything is computed: the Grid's boundaries must be ones the solver knows.
void check_parameters(Context& ctx) {
  const int dim = ctx.grid().dimension();
  const CoordinateSystem cs = ctx.grid().coordinates();
  const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& hi = ctx.param<std::vector<double>>("Grid", "xmax");
  for (const char* side : {"boundary_lower", "boundary_upper"}) {
    const auto& names = ctx.param<std::vector<std::string>>("Grid", side);
    for (int d = 0; d < dim; ++d) {
      const auto u = static_cast<std::size_t>(d);
      try {
        (void)boundary_kind(names[u], d, cs, hi[u] - lo[u]);
      } catch (const std::invalid_argument& e) {
        throw InputError(ctx.params().origin("Grid", side), e.what());
      }
    }
  }
}

}  // namespace
}  // namespace remnant::xcfc

REMNANT_REGISTER_THORN(XCFC) {
  using namespace remnant::xcfc;
  reg.function("XCFC_CheckParameters", check_parameters);
  reg.function("XCFC_Initial", initial_solve);
  reg.function("XCFC_Solve", evolution_step);
  reg.persistent_state([](remnant::Context& ctx) { return save_persistent(runtime(ctx)); },
                       [](remnant::Context& ctx, const std::string& text) { restore_persistent(runtime(ctx), text); });
}
