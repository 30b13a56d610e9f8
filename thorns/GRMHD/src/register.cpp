// GRMHD (hydrodynamics): binds the scheduled functions of thorn.yaml.
#include <mpi.h>

#include <sstream>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/settings.hpp"
#include "EOS/eos.hpp"
#include "GRMHD/con2prim_sweep.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "rhs.hpp"
#include "shock_tube.hpp"
#include "time_step.hpp"

namespace remnant::grmhd {
namespace {

RhsSettings rhs_settings(const Context& ctx) {
  RhsSettings s;
  s.reconstruction = parse_reconstruction(ctx.param<std::string>("GRMHD", "reconstruction"));
  s.metric_faces = ctx.param<std::string>("GRMHD", "metric_face_interpolation") == "cubic"
                       ? MetricFaceInterpolation::cubic
                       : MetricFaceInterpolation::linear;
  return s;
}

void check_parameters(Context& ctx) {
  const RhsSettings s = rhs_settings(ctx);
  for (Block* b : ctx.grid().local_blocks())
    for (int d = 0; d < 3; ++d)
      if (b->ng[d] > 0 && b->ng[d] < ghosts_needed(s.reconstruction))
        throw InputError(ctx.params().origin("GRMHD", "reconstruction"),
                         "GRMHD::reconstruction = " + ctx.param<std::string>("GRMHD", "reconstruction") + " needs " +
                             std::to_string(ghosts_needed(s.reconstruction)) + " ghost zones; Grid::ghost_zones is " +
                             std::to_string(b->ng[d]));
}

// Counts over all ranks; a fatal policy rule stops the run (paper: rules 1, 3, 5).
void report(Context& ctx, const con2prim::Diagnostics& d, const char* where, const std::string& fatal_cell = "") {
  std::uint64_t local[3] = {d.fatal_cells, d.count(con2prim::Status::not_converged) + d.count(con2prim::Status::no_bracket) +
                                               d.count(con2prim::Status::non_finite) + d.count(con2prim::Status::invalid_input),
                            d.cells};
  std::uint64_t global[3];
  MPI_Allreduce(local, global, 3, MPI_UINT64_T, MPI_SUM, ctx.comm());
  if (global[0] > 0) {
    std::ostringstream m;
    m << where << ": a fatal error-policy rule fired in " << global[0] << " cells (rho > rho_max, eps > eps_max or T > T_max)";
    if (!fatal_cell.empty()) m << "; first on this rank: " << fatal_cell;
    throw RunError(m.str());
  }
  if (global[1] > 0 && ctx.rank() == 0) {
    std::ostringstream m;
    m << where << ": primitive recovery failed in " << global[1] << " of " << global[2]
      << " cells (set to atmosphere or best estimate)";
    ctx.warn(m.str());
  }
}

void initial_cons(Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto& settings = ctx.service<con2prim::Settings>("con2prim");
  const auto& atm = ctx.service<atmosphere::Atmosphere>("atmosphere");
  const Groups g = Groups::of(ctx);
  con2prim::Diagnostics diag;
  for (Block* b : ctx.grid().local_blocks())
    prim_to_cons_block(eos, settings, atm, g, *b, diag);
  report(ctx, diag, "GRMHD_InitialCons");
}

void calc_rhs(Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const RhsSettings s = rhs_settings(ctx);
  const Groups g = Groups::of(ctx);
  for (Block* b : ctx.grid().local_blocks()) compute_block_fluxes(eos, s, g, *b);
  // Refluxing: coarse faces shared with finer blocks take the fine fluxes (no-op on a uniform grid).
  std::vector<int> faces;
  for (int d = 0; d < ctx.grid().dimension(); ++d) faces.push_back(g.flux[d]);
  ctx.grid().correct_fluxes(faces);
  for (Block* b : ctx.grid().local_blocks()) compute_block_rhs(g, *b);
}

void con2prim(Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto& settings = ctx.service<con2prim::Settings>("con2prim");
  const auto& atm = ctx.service<atmosphere::Atmosphere>("atmosphere");
  const Groups g = Groups::of(ctx);
  con2prim::Diagnostics diag;
  std::string fatal_cell;
  for (Block* b : ctx.grid().local_blocks()) recover_block(eos, settings, atm, g, *b, diag, fatal_cell);
  report(ctx, diag, "GRMHD_Con2Prim", fatal_cell);
}

double inverse_dt(Context& ctx) {
  const Groups g = Groups::of(ctx);
  double inv = 0;
  for (Block* b : ctx.grid().local_blocks())
    inv = std::max(inv, block_inverse_dt(g, *b));
  return inv;
}

}  // namespace
}  // namespace remnant::grmhd

REMNANT_REGISTER_THORN(GRMHD) {
  using namespace remnant::grmhd;
  reg.function("GRMHD_CheckParameters", check_parameters);
  reg.function("GRMHD_ShockTube", shock_tube_initial_data);
  reg.function("GRMHD_InitialCons", initial_cons);
  reg.function("GRMHD_RHS", calc_rhs);
  reg.function("GRMHD_Con2Prim", con2prim);
  reg.function("GRMHD_RecoverInitialPrimitives", con2prim);  // in XCFC's groups (thorn.yaml)
  reg.function("GRMHD_RecoverWithNewMetric", con2prim);
  reg.inverse_dt_limit(inverse_dt);
}
