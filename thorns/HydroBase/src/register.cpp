// HydroBase: binds the scheduled functions of thorn.yaml.
#include <algorithm>

#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/sweeps.hpp"
#include "remnant/registrar.hpp"

namespace remnant::hydrobase {
namespace {

void initial_cons(Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto& settings = ctx.service<con2prim::Settings>("con2prim");
  const auto& atm = ctx.service<atmosphere::Atmosphere>("atmosphere");
  const MatterGroups g = MatterGroups::of(ctx);
  con2prim::Diagnostics diag;
  for (Block* b : ctx.grid().local_blocks()) {
    prim_to_cons_block(eos, settings, atm, g, *b, diag);
    std::fill_n(b->data(g.budget), b->size(g.budget), 0.0);  // the budget starts with the evolution
  }
  report_recovery(ctx, diag, "HydroBase_InitialCons");
}

}  // namespace
}  // namespace remnant::hydrobase

REMNANT_REGISTER_THORN(HydroBase) {
  using namespace remnant::hydrobase;
  reg.function("HydroBase_InitialCons", initial_cons);
  reg.function("HydroBase_InitialField", [](remnant::Context& ctx) {
    const FieldGroups g = FieldGroups::of(ctx);
    for (remnant::Block* b : ctx.grid().local_blocks()) cell_centred_field(g, *b);
  });
  // In the metric solver's groups (thorn.yaml): the sources of its equations, and the same recovery
  // sweep as the evolution's with the new psi (followed by the sources of the recovered matter).
  reg.function("HydroBase_MatterSources", fill_matter_sources);
  reg.function("HydroBase_InitialMatterSources", fill_matter_sources);
  reg.function("HydroBase_ConservedFromPrimitives", [](remnant::Context& ctx) {
    conserved_from_primitives(ctx);
    fill_matter_sources(ctx);
  });
  reg.function("HydroBase_RecoverInitialPrimitives", [](remnant::Context& ctx) {
    recover_all(ctx, "HydroBase_RecoverInitialPrimitives");
    fill_matter_sources(ctx);
  });
  reg.function("HydroBase_RecoverWithNewMetric", [](remnant::Context& ctx) {
    recover_all(ctx, "HydroBase_RecoverWithNewMetric");
    fill_matter_sources(ctx);
  });
}
