#pragma once
// Primitive recovery and atmosphere over the interior of a block (after every MoL substep, and after
// a metric solve), and the conserved variables from primitives (initial data). Both undo / apply the
// psi^6 densitisation of HydroBase::cons.
#include <string>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/report.hpp"
#include "Con2Prim/settings.hpp"
#include "EOS/eos.hpp"
#include "remnant/context.hpp"

namespace remnant::hydrobase {

// The group ids the sweeps use, resolved once per scheduled call.
struct MatterGroups {
  int cons = -1, prim = -1, metric = -1;
  int budget = -1;  // HydroBase::mass_budget: the sweep adds the D it changes (atmosphere, policy); -1: none
  int bvec = -1;    // HydroBase::Bvec (cell-centred B^i, not densitised) when the field is evolved; -1: none
  static MatterGroups of(const Context& ctx);
};

// cons -> prim with the paper's recovery; cons is overwritten with the conserved variables of the
// corrected primitives (atmosphere, policy; with a field, the atmosphere's b^2/rho cap).
// The first cell in which a fatal rule fired, if any, is described in `fatal_cell`.
void recover_block(const eos::EOS& eos, const con2prim::Settings& s, const atmosphere::Atmosphere& atm,
                   const MatterGroups& g, Block& b, con2prim::Diagnostics& diag, std::string& fatal_cell);

// Initial data: the primitives (rho, v, eps, Ye) are made consistent (atmosphere, error policy with
// eps trusted, T from eps, p and cs2 from the EOS) and the conserved variables computed. With a
// field (g.bvec): the atmosphere's magnetisation cap, and *max_sigma (if given) raised to the largest
// b^2/rho of the cells outside the atmosphere.
void prim_to_cons_block(const eos::EOS& eos, const con2prim::Settings& s, const atmosphere::Atmosphere& atm,
                        const MatterGroups& g, Block& b, con2prim::Diagnostics& diag, double* max_sigma = nullptr);

// Every local block through recover_block with the published EOS, con2prim settings and atmosphere;
// the counts are reported (and a fatal policy rule stops the run) as `where`. Collective.
void recover_all(Context& ctx, const char* where);

// Sums the diagnostics over all ranks; throws RunError when a fatal policy rule fired anywhere (paper:
// rules 1, 3, 5) and warns (rank 0) about failed recoveries. Collective.
void report_recovery(Context& ctx, const con2prim::Diagnostics& d, const char* where, const std::string& fatal_cell = "");

// Spacetime::matter_sources from the current matter: E~ = D + tau, S~_i, S~ = S~_i v^i + 3 psi^6 p
// (all densitised). Runs in the metric solver's source and recovery hooks.
void fill_matter_sources(Context& ctx);

// Initial data given as primitives: HydroBase::cons = psi^6 cons(prim, psi^4 f) with the current psi
// (and W from v), on the interior.
void conserved_from_primitives(Context& ctx);

}  // namespace remnant::hydrobase
