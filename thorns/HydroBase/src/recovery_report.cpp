// Group ids, the whole-grid recovery, and the rank-summed report of the error policy.
#include <mpi.h>

#include <sstream>

#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/sweeps.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::hydrobase {

MatterGroups MatterGroups::of(const Context& ctx) {
  MatterGroups g;
  g.cons = vars::HydroBase::cons::id(ctx);
  g.prim = vars::HydroBase::prim::id(ctx);
  g.metric = vars::Spacetime::metric::id(ctx);
  g.budget = vars::HydroBase::mass_budget::id(ctx);
  for (int id : {g.cons, g.prim, g.metric, g.budget}) ctx.check_access(id);
  g.bvec = FieldGroups::of(ctx).bvec;
  return g;
}

void report_recovery(Context& ctx, const con2prim::Diagnostics& d, const char* where, const std::string& fatal_cell) {
  std::uint64_t local[4] = {d.fatal_cells, d.count(con2prim::Status::not_converged) + d.count(con2prim::Status::no_bracket) +
                                               d.count(con2prim::Status::non_finite) + d.count(con2prim::Status::invalid_input),
                            d.cells, d.count(con2prim::Status::inaccurate) + d.count(con2prim::Status::ambiguous)};
  std::uint64_t global[4];
  MPI_Allreduce(local, global, 4, MPI_UINT64_T, MPI_SUM, ctx.comm());
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
  // Recoveries that do not reproduce their conserved variables (or not uniquely): kept, counted, warned.
  if (global[3] > 0 && ctx.rank() == 0) {
    std::ostringstream m;
    m << where << ": " << global[3] << " of " << global[2]
      << " recoveries inaccurate or ambiguous (conserved variables not reproduced to Con2Prim::accuracy, or "
         "not uniquely: acausal table); the closest state is kept";
    ctx.warn(m.str());
  }
}

void recover_all(Context& ctx, const char* where) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto& settings = ctx.service<con2prim::Settings>("con2prim");
  const auto& atm = ctx.service<atmosphere::Atmosphere>("atmosphere");
  const MatterGroups g = MatterGroups::of(ctx);
  con2prim::Diagnostics diag;
  std::string fatal_cell;
  for (Block* b : ctx.grid().local_blocks()) recover_block(eos, settings, atm, g, *b, diag, fatal_cell);
  report_recovery(ctx, diag, where, fatal_cell);
}

}  // namespace remnant::hydrobase
