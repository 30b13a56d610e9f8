// GRMHD: binds the scheduled functions of thorn.yaml.
#include <algorithm>
#include <span>
#include <vector>
#include <type_traits>

#include "EOS/eos.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/sweeps.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "constrained_transport.hpp"
#include "ct_faces.hpp"
#include "mass_budget.hpp"
#include "mhd_fluxes.hpp"
#include "positivity_limiter.hpp"
#include "rhs.hpp"
#include "alfven_wave.hpp"
#include "shock_tube.hpp"
#include "shock_tube_field.hpp"
#include "time_step.hpp"

namespace remnant::grmhd {
namespace {

RhsSettings rhs_settings(const Context& ctx) {
  RhsSettings s;
  s.reconstruction = parse_reconstruction(ctx.param<std::string>("GRMHD", "reconstruction"));
  s.metric_faces = ctx.param<std::string>("GRMHD", "metric_face_interpolation") == "cubic"
                       ? MetricFaceInterpolation::cubic
                       : MetricFaceInterpolation::linear;
  s.well_balanced = ctx.param<std::string>("GRMHD", "well_balanced") == "isentropic";
  return s;
}

// Pass 2's part of GRMHD::well_balanced: the face metric of the fluxes and the ideal gas's Gamma.
WellBalancedSources well_balanced_sources(const eos::EOS& eos, const RhsSettings& s) {
  WellBalancedSources wb;
  if (!s.well_balanced) return wb;
  wb.faces = s.metric_faces;
  eos.visit([&](const auto& e) {
    if constexpr (reconstructs_pressure<std::decay_t<decltype(e)>>) {
      wb.on = true;
      wb.isentrope.gamma = e.gamma();
    }
  });
  return wb;
}

// A magnetic-field parameter in a run without a field is an input error, not silently ignored.
void check_field_parameters(const Context& ctx) {
  if (hydrobase::magnetic_field_evolved(ctx)) return;
  auto refuse = [&](const char* name) {
    throw InputError(ctx.params().origin("GRMHD", name),
                     std::string("GRMHD::") + name +
                         " is a magnetic-field parameter, but HydroBase::magnetic_field = none: set "
                         "HydroBase::magnetic_field: evolved, or remove it");
  };
  for (const char* name : {"shock_field_left", "shock_field_right"})
    for (double v : ctx.param<std::vector<double>>("GRMHD", name))
      if (v != 0) refuse(name);
  if (ctx.param<double>("GRMHD", "field_potential_amplitude") != 0) refuse("field_potential_amplitude");
  if (ctx.param<std::string>("GRMHD", "emf") != "uct_hll") refuse("emf");
  if (ctx.param<std::string>("GRMHD", "emf_reconstruction") != "mc") refuse("emf_reconstruction");
  if (ctx.param<std::string>("GRMHD", "initial_data") == "alfven_wave") refuse("initial_data");
}

void check_parameters(Context& ctx) {
  check_field_parameters(ctx);
  if (ctx.param<std::string>("GRMHD", "well_balanced") != "none" && ctx.param<std::string>("EOS", "type") != "ideal_gas")
    throw InputError(ctx.params().origin("GRMHD", "well_balanced"),
                     "GRMHD::well_balanced = " + ctx.param<std::string>("GRMHD", "well_balanced") +
                         " needs EOS::type = ideal_gas (the isentrope in closed form); EOS::type is " +
                         ctx.param<std::string>("EOS", "type") + ": set GRMHD::well_balanced: none");
  check_positivity_limiter(ctx);
  for (const char* name : {"reconstruction", "emf_reconstruction"}) {
    if (std::string(name) == "emf_reconstruction" && !hydrobase::magnetic_field_evolved(ctx)) continue;
    const std::string& value = ctx.param<std::string>("GRMHD", name);
    const int needed = ghosts_needed(parse_reconstruction(value));
    for (Block* b : ctx.grid().local_blocks())
      for (int d = 0; d < 3; ++d)
        if (b->ng[d] > 0 && b->ng[d] < needed)
          throw InputError(ctx.params().origin("GRMHD", name),
                           std::string("GRMHD::") + name + " = " + value + " needs " + std::to_string(needed) +
                               " ghost zones; Grid::ghost_zones is " + std::to_string(b->ng[d]));
  }
}

void calc_rhs(Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const RhsSettings s = rhs_settings(ctx);
  const Groups g = Groups::of(ctx);
  for (Block* b : ctx.grid().local_blocks()) compute_block_fluxes(eos, s, g, *b);
  apply_positivity_limiter(ctx, g);
  // Refluxing: coarse faces shared with finer blocks take the fine fluxes (no-op on a uniform grid).
  std::vector<int> faces;
  for (int d = 0; d < ctx.grid().dimension(); ++d) faces.push_back(g.flux[d]);
  // No flux crosses the faces of unused directions: zero, so that every declared output is defined.
  for (int d = ctx.grid().dimension(); d < 3; ++d)
    for (Block* b : ctx.grid().local_blocks()) std::fill(b->data(g.flux[d]), b->data(g.flux[d]) + b->size(g.flux[d]), 0.0);
  ctx.grid().correct_fluxes(faces);
  const DomainCells dom = DomainCells::of(ctx);
  const WellBalancedSources wb = well_balanced_sources(eos, s);
  for (Block* b : ctx.grid().local_blocks()) {
    compute_block_rhs(g, *b, wb);
    outflow_rhs_block(g, dom, *b);  // the rest mass crossing the domain boundary (mass budget)
  }
}

// The MHD right-hand side: fluxes and face Riemann data, refluxing, edge EMFs, edge correction at
// refinement boundaries, CT face update, flux divergence and magnetised sources.
void calc_rhs_mhd(Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const RhsSettings s = rhs_settings(ctx);
  const Groups g = Groups::of(ctx);
  const MhdGroups mg = MhdGroups::of(ctx);
  const std::string& emf = ctx.param<std::string>("GRMHD", "emf");
  const EmfScheme scheme = emf == "arithmetic"    ? EmfScheme::arithmetic
                           : emf == "uct_contact" ? EmfScheme::uct_contact
                                                  : EmfScheme::uct_hll;
  const Reconstruction edge_rec = parse_reconstruction(ctx.param<std::string>("GRMHD", "emf_reconstruction"));
  // The face data of the EMFs (ct_faces.hpp): one block's at a time, reused. uct_hll and arithmetic
  // read only them and the face fields, not the fluxes that the limiter and the Grid correct below,
  // so a block's EMFs are computed right after its sweep. uct_contact upwinds with the corrected mass
  // fluxes: it keeps every block's induction fluxes (its only face data) until then.
  thread_local CtFaceStorage face_data;
  thread_local std::vector<CtFaceStorage> induction_fluxes;
  const bool contact = scheme == EmfScheme::uct_contact;
  const std::span<Block* const> blocks = ctx.grid().local_blocks();
  if (contact) induction_fluxes.resize(blocks.size());
  else std::vector<CtFaceStorage>().swap(induction_fluxes);
  const auto bind = [&](std::size_t i, Block& b) {
    CtFaces ct;
    face_data.bind(b, g, ct, 0, contact ? kFluxNext : kNumCt);
    if (contact) induction_fluxes[i].bind(b, g, ct, kFluxNext, kNumCt);
    return ct;
  };
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const CtFaces ct = bind(i, *blocks[i]);
    compute_block_fluxes_mhd(eos, s, g, mg, ct, *blocks[i], scheme);
    if (!contact) edge_emfs(scheme, mg, ct, *blocks[i], edge_rec);
  }
  apply_positivity_limiter(ctx, g);
  std::vector<int> faces;
  for (int d = 0; d < ctx.grid().dimension(); ++d) faces.push_back(g.flux[d]);
  for (int d = ctx.grid().dimension(); d < 3; ++d)
    for (Block* b : blocks) std::fill(b->data(g.flux[d]), b->data(g.flux[d]) + b->size(g.flux[d]), 0.0);
  ctx.grid().correct_fluxes(faces);
  if (contact)
    for (std::size_t i = 0; i < blocks.size(); ++i) edge_emfs(scheme, mg, g, bind(i, *blocks[i]), *blocks[i], edge_rec);
  ctx.grid().correct_edges(mg.emf);
  const DomainCells dom = DomainCells::of(ctx);
  const WellBalancedSources wb = well_balanced_sources(eos, s);
  for (Block* b : blocks) {
    face_rhs(mg, *b);
    compute_block_rhs_mhd(g, mg.bvec, *b, wb);
    outflow_rhs_block(g, dom, *b);
  }
}

void con2prim(Context& ctx) { hydrobase::recover_all(ctx, "GRMHD_Con2Prim"); }

void cell_centred_field(Context& ctx) {
  const hydrobase::FieldGroups g = hydrobase::FieldGroups::of(ctx);
  for (Block* b : ctx.grid().local_blocks()) hydrobase::cell_centred_field(g, *b);
}

double inverse_dt(Context& ctx) {
  const Groups g = Groups::of(ctx);
  const int bvec = hydrobase::FieldGroups::of(ctx).bvec;
  double inv = 0;
  for (Block* b : ctx.grid().local_blocks())
    inv = std::max(inv, bvec >= 0 ? block_inverse_dt_mhd(g, bvec, *b) : block_inverse_dt(g, *b));
  return inv;
}

}  // namespace
}  // namespace remnant::grmhd

REMNANT_REGISTER_THORN(GRMHD) {
  using namespace remnant::grmhd;
  reg.function("GRMHD_CheckParameters", check_parameters);
  reg.function("GRMHD_ShockTube", shock_tube_initial_data);
  reg.function("GRMHD_AlfvenWave", alfven_wave_initial_data);
  reg.function("GRMHD_InitialField", [](remnant::Context& ctx) {
    const std::string& id = ctx.param<std::string>("GRMHD", "initial_data");
    if (id == "shock_tube") shock_tube_field(ctx);
    if (id == "alfven_wave") alfven_wave_field(ctx);
  });
  reg.function("GRMHD_RHS", calc_rhs);
  reg.function("GRMHD_RHS_MHD", calc_rhs_mhd);
  reg.function("GRMHD_CellCentredField", cell_centred_field);
  reg.function("GRMHD_CellCentredFieldAfterRegrid", cell_centred_field);
  reg.function("GRMHD_Con2Prim", con2prim);
  reg.inverse_dt_limit(inverse_dt);
}
