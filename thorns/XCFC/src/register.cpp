// XCFC: binds the scheduled functions of thorn.yaml. The solve (solve_sequence), its cadence and
// the metric between solves (cadence), the per-simulation state (runtime) and the log (solve_log)
// live beside it.
#include <stdexcept>
#include <string>

#include "cadence.hpp"
#include "grid_bridge.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "runtime.hpp"
#include "solve_sequence.hpp"

namespace remnant::xcfc {
namespace {

// Before anything is computed: the grid's domain faces must be ones the solver knows.
void check_parameters(Context& ctx) {
  const Domain domain = ctx.grid().domain();
  for (int side = 0; side < 2; ++side)
    for (int d = 0; d < domain.faces.dimension; ++d) {
      try {
        check_face(domain, d, side);
      } catch (const std::invalid_argument& e) {
        // The location of the Grid's parameter that set the face, for the message.
        throw InputError(ctx.params().origin("Grid", side == 0 ? "boundary_lower" : "boundary_upper"), e.what());
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
