#include "solve_sequence.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "XCFC/xcfc_system.hpp"
#include "cadence.hpp"
#include "grid_bridge.hpp"
#include "runtime.hpp"
#include "solve_log.hpp"

namespace remnant::xcfc {
namespace {

SolveSettings settings(const Context& ctx, bool initial) {
  SolveSettings s;
  s.tolerance = ctx.param<double>("XCFC", initial ? "tolerance_initial" : "tolerance");
  s.max_cycles = static_cast<int>(ctx.param<std::int64_t>("XCFC", "max_cycles"));
  s.pre_sweeps = s.post_sweeps = static_cast<int>(ctx.param<std::int64_t>("XCFC", "sweeps"));
  s.full_multigrid = initial;
  return s;
}

// The matter sources of one solve.
struct Sources {
  CompositeField E;
  VectorField S;
};

Sources gather_sources(const GridBridge& br, const MatterGroups& g) {
  Sources s;
  s.E = br.gather_cells([&](Block& b) {
    const Field D = b.field(g.cons, 0), tau = b.field(g.cons, 4);
    return [=](int i, int j, int k) { return D(i, j, k) + tau(i, j, k); };
  });
  for (int d = 0; d < 3; ++d) s.S[d] = br.gather(g.cons, 1 + d);
  return s;
}

void store_lapse_shift(const GridBridge& br, const MatterGroups& g, int potentials, const XcfcState& st) {
  br.scatter(st.alpha(), g.metric, 1);
  for (int d = 0; d < 3; ++d) br.scatter(st.beta[d], g.metric, 2 + d);
  for (int a = 0; a < 3; ++a) {
    br.scatter(st.X_potentials.B[a], potentials, a);
    br.scatter(st.beta_potentials.B[a], potentials, 4 + a);
  }
  br.scatter(st.X_potentials.chi, potentials, 3);
  br.scatter(st.beta_potentials.chi, potentials, 7);
}

// What every xCFC solve works with, set up from the warm start; finish() solves for alpha psi and
// beta with the final matter and records the solve.
struct Solve {
  const std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  XcfcSolver& sv;
  const GridBridge br;
  const MatterGroups g;
  const int potentials;
  const SolveSettings set;
  XcfcState st;
  XcfcStats stats;

  Solve(Context& ctx, bool initial)
      : sv(solver(ctx)), br(ctx, sv.multigrid()), g(MatterGroups::of(ctx)), potentials(ctx.var("XCFC::potentials")),
        set(settings(ctx, initial)) {
    load_warm_start(ctx, br, g, potentials, st);
  }

  void finish(Context& ctx, const Sources& src, const char* reason) {
    const CompositeField S =
        br.gather_cells([&](Block& b) { return DensitisedStressTrace(b, g); });
    sv.solve_lapse_and_shift(src.E, src.S, S, st, stats, set);
    shift_potentials(ctx, potentials);
    store_lapse_shift(br, g, potentials, st);
    record_history(ctx);
    warn_unconverged(ctx, stats);
    write_tsv(ctx, reason, stats, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
};

// Initial data given as primitives: iterate psi with the primitives fixed (E~ = psi^6 E changes
// with psi), then the lapse and shift.
void solve_from_primitives(Context& ctx) {
  Solve s(ctx, true);
  const int max_iter = static_cast<int>(ctx.param<std::int64_t>("XCFC", "initial_iterations"));
  double change = 0;
  for (int it = 0; it < max_iter; ++it) {
    conserved_from_primitives(ctx, s.g);
    const Sources src = gather_sources(s.br, s.g);
    const CompositeField old = s.st.psi;
    s.sv.solve_conformal_factor(src.E, src.S, s.st, s.stats, s.set);
    s.br.scatter(s.st.psi, s.g.metric, 0);
    change = 0;
    for (std::size_t n = 0; n < old.part.size(); ++n)
      for (std::size_t q = 0; q < old.part[n].size(); ++q) change = std::max(change, std::abs(s.st.psi.part[n][q] - old.part[n][q]));
    if (change <= s.set.tolerance) break;
  }
  char m[200];
  std::snprintf(m, sizeof m, "XCFC: initial psi from the primitives, last change %.2e", change);
  ctx.info(m);
  conserved_from_primitives(ctx, s.g);
  s.finish(ctx, gather_sources(s.br, s.g), "initial");
}

}  // namespace

void recover_with_new_psi(Context& ctx, const MatterGroups& g) {
  const std::uint64_t fatal = recover_primitives(ctx, g);
  std::uint64_t total = 0;
  MPI_Allreduce(&fatal, &total, 1, MPI_UINT64_T, MPI_SUM, ctx.comm());
  if (total > 0) throw RunError("XCFC: a fatal error-policy rule fired in " + std::to_string(total) + " cells in the recovery with the new psi");
}

void solve_sequence(Context& ctx, bool initial, const char* reason) {
  Solve s(ctx, initial);
  const Sources src = gather_sources(s.br, s.g);
  s.sv.solve_conformal_factor(src.E, src.S, s.st, s.stats, s.set);
  s.br.scatter(s.st.psi, s.g.metric, 0);
  recover_with_new_psi(ctx, s.g);
  s.finish(ctx, gather_sources(s.br, s.g), reason);  // the recovery may have reset cells to atmosphere
}

void initial_solve(Context& ctx) {
  runtime(ctx) = Runtime{};
  const std::string& mode = ctx.param<std::string>("XCFC", "initial_metric");
  if (mode == "from_primitives") solve_from_primitives(ctx);
  else if (mode == "from_conserved") solve_sequence(ctx, true, "initial");
}

double psi_residual(Context& ctx) {
  XcfcSolver& sv = solver(ctx);
  const GridBridge br(ctx, sv.multigrid());
  const MatterGroups g = MatterGroups::of(ctx);
  XcfcState st;
  st.psi = br.gather(g.metric, 0);
  const Sources src = gather_sources(br, g);
  return sv.conformal_factor_residual(src.E, st);
}

}  // namespace remnant::xcfc
