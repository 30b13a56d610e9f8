// HydroBase: binds the scheduled functions of thorn.yaml.
#include <mpi.h>

#include <algorithm>
#include <string>

#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/outflow_boundary.hpp"
#include "HydroBase/sweeps.hpp"
#include "remnant/error.hpp"
#include "remnant/registrar.hpp"

namespace remnant::hydrobase {
namespace {

void initial_cons(Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto& settings = ctx.service<con2prim::Settings>("con2prim");
  const auto& atm = ctx.service<atmosphere::Atmosphere>("atmosphere");
  const MatterGroups g = MatterGroups::of(ctx);
  con2prim::Diagnostics diag;
  double max_sigma = 0;  // b^2/rho outside the atmosphere (with a field)
  for (Block* b : ctx.grid().local_blocks()) {
    prim_to_cons_block(eos, settings, atm, g, *b, diag, g.bvec >= 0 ? &max_sigma : nullptr);
    std::fill_n(b->data(g.budget), b->size(g.budget), 0.0);  // the budget starts with the evolution
  }
  report_recovery(ctx, diag, "HydroBase_InitialCons");
  if (g.bvec >= 0) {
    MPI_Allreduce(MPI_IN_PLACE, &max_sigma, 1, MPI_DOUBLE, MPI_MAX, ctx.comm());
    if (max_sigma > atm.sigma_max)
      throw InputError(ctx.params().origin("Atmosphere", "sigma_max"),
                       "the initial magnetic field makes b^2/rho = " + std::to_string(max_sigma) +
                           " outside the atmosphere, above Atmosphere::sigma_max = " + std::to_string(atm.sigma_max) +
                           ": weaken the field or raise the cap");
  }
}

// Bvec = Bface / psi^6 with the current psi: the metric solver changes psi under the densitised face
// fields, so its hooks refresh the cell-centred field before using it (no-op without a field).
void refresh_field(Context& ctx) {
  const FieldGroups g = FieldGroups::of(ctx);
  if (g.bvec < 0) return;
  for (Block* b : ctx.grid().local_blocks()) cell_centred_field(g, *b);
}

}  // namespace
}  // namespace remnant::hydrobase

REMNANT_REGISTER_THORN(HydroBase) {
  using namespace remnant::hydrobase;
  reg.function("HydroBase_InitialCons", initial_cons);
  reg.function("HydroBase_OutflowBoundary", register_outflow_boundary);
  reg.function("HydroBase_InitialField", [](remnant::Context& ctx) {
    const FieldGroups g = FieldGroups::of(ctx);
    for (remnant::Block* b : ctx.grid().local_blocks()) cell_centred_field(g, *b);
  });
  // In the metric solver's groups (thorn.yaml): the sources of its equations, and the same recovery
  // sweep as the evolution's with the new psi (followed by the sources of the recovered matter).
  // Each also as *_MHD (thorn.yaml: the same work, declaring Bvec and the faces, with a field).
  for (const std::string suffix : {"", "_MHD"}) {
    reg.function("HydroBase_MatterSources" + suffix, fill_matter_sources);
    reg.function("HydroBase_InitialMatterSources" + suffix, fill_matter_sources);
    reg.function("HydroBase_ConservedFromPrimitives" + suffix, [](remnant::Context& ctx) {
      refresh_field(ctx);
      conserved_from_primitives(ctx);
      fill_matter_sources(ctx);
    });
    reg.function("HydroBase_RecoverInitialPrimitives" + suffix, [](remnant::Context& ctx) {
      refresh_field(ctx);
      recover_all(ctx, "HydroBase_RecoverInitialPrimitives");
      fill_matter_sources(ctx);
    });
    reg.function("HydroBase_RecoverWithNewMetric" + suffix, [](remnant::Context& ctx) {
      refresh_field(ctx);
      recover_all(ctx, "HydroBase_RecoverWithNewMetric");
      fill_matter_sources(ctx);
    });
  }
}
