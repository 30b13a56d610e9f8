// XCFC: binds the scheduled functions of thorn.yaml. The solve (solve_sequence), its cadence and
// the metric between solves (cadence), the per-simulation state (runtime) and the log (solve_log)
// live beside it.
#include <stdexcept>
#include <string>

#include "cadence.hpp"
#include "grid_bridge.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "remnant/vars/XCFC.hpp"
#include "runtime.hpp"
#include "solve_sequence.hpp"
#include "stage_metric.hpp"

namespace remnant::xcfc {
namespace {

// Before anything is computed: the grid's domain faces must be ones the solver knows.
void check_parameters(Context& ctx) {
  // The vector solves treat B as a vector in Cartesian components (vector_poisson.cpp); the warm
  // starts the Grid keeps must be declared so, or their symmetry images take the wrong signs.
  for (const char* name : {"XCFC::potentials", "XCFC::potentials_before"}) {
    const VariableGroupSpec& g = ctx.vars().group(ctx.var(name));
    for (int a = 0; a < 3; ++a)
      for (int first : {vars::XCFC::potentials::idx::XB, vars::XCFC::potentials::idx::betaB})
        if (!g.cartesian_basis || g.components[static_cast<std::size_t>(first + a)].kind != TensorKind::vector)
          throw InputError(g.where, std::string(name) + " must declare XB and betaB as `vector` with `basis: cartesian`");
  }
  check_stage_metric(ctx);
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
  // The initial metric (group XCFC_Initial, one pass).
  reg.predicate("XCFC_InitialPass", initial_pass);
  reg.predicate("XCFC_InitialSourcesDue", initial_sources_due);
  reg.predicate("XCFC_PsiIterationDue", psi_iteration_due);
  reg.function("XCFC_InitialPsiIteration", initial_psi_iteration);
  reg.function("XCFC_InitialConformalFactor", initial_conformal_factor);
  reg.function("XCFC_InitialLapseAndShift", initial_lapse_and_shift);
  // Every step: the cadence, then the passes of the group XCFC_Solve.
  reg.function("XCFC_Cadence", cadence);
  reg.predicate("XCFC_NextPass", next_pass);
  reg.function("XCFC_Extrapolate", extrapolate);
  reg.predicate("XCFC_SourcesDue", sources_due);
  reg.function("XCFC_VectorPotential", step_vector_potential);
  reg.function("XCFC_ConformalFactor", step_conformal_factor);
  reg.predicate("XCFC_RecoveryDue", recovery_due);
  reg.function("XCFC_Lapse", step_lapse);
  reg.function("XCFC_Shift", step_shift);
  reg.function("XCFC_ResidualTrigger", residual_trigger);
  // Inside the matter step (XCFC::stage_metric = extrapolate): the metric at each stage's time.
  reg.function("XCFC_StageMetric", stage_metric);
  reg.persistent_state([](remnant::Context& ctx) { return save_persistent(runtime(ctx)); },
                       [](remnant::Context& ctx, const std::string& text) { restore_persistent(runtime(ctx), text); });
}
