#include "solve_sequence.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "XCFC/xcfc_system.hpp"
#include "cadence.hpp"
#include "grid_bridge.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"
#include "remnant/vars/XCFC.hpp"
#include "runtime.hpp"
#include "solve_log.hpp"

namespace remnant::xcfc {
namespace {

using Cons = vars::HydroBase::cons;
using Metric = vars::Spacetime::metric;
using Potentials = vars::XCFC::potentials;

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
    const Cons cons(b, g.cons);
    const Field D = cons.field(Cons::idx::D), tau = cons.field(Cons::idx::tau);
    return [=](int i, int j, int k) { return D(i, j, k) + tau(i, j, k); };
  });
  for (int d = 0; d < 3; ++d) s.S[d] = br.gather(g.cons, Cons::idx::S + d);
  return s;
}

void store_lapse_shift(const GridBridge& br, const MatterGroups& g, int potentials, const XcfcState& st) {
  br.scatter(st.alpha(), g.metric, Metric::idx::alpha);
  for (int d = 0; d < 3; ++d) br.scatter(st.beta[d], g.metric, Metric::idx::beta + d);
  for (int a = 0; a < 3; ++a) {
    br.scatter(st.X_potentials.B[a], potentials, Potentials::idx::XBx + a);
    br.scatter(st.beta_potentials.B[a], potentials, Potentials::idx::betaBx + a);
  }
  br.scatter(st.X_potentials.chi, potentials, Potentials::idx::Xchi);
  br.scatter(st.beta_potentials.chi, potentials, Potentials::idx::betachi);
}

}  // namespace

// What every xCFC solve works with, set up from the warm start and kept in the runtime between the
// scheduled steps.
struct SolveInProgress {
  const std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  XcfcSolver& sv;
  const GridBridge br;
  const MatterGroups g;
  const int potentials;
  const SolveSettings set;
  XcfcState st;
  XcfcStats stats;
  Sources src;  // the matter sources of the current step

  SolveInProgress(Context& ctx, bool initial)
      : sv(solver(ctx)), br(ctx, sv.multigrid()), g(MatterGroups::of(ctx)), potentials(ctx.var("XCFC::potentials")),
        set(settings(ctx, initial)) {
    load_warm_start(ctx, br, g, potentials, st);
  }
};

namespace {

SolveInProgress* in_progress(Context& ctx) { return runtime(ctx).solve.get(); }

// alpha psi with the final matter (after the recovery: it may have reset cells to atmosphere).
void lapse(SolveInProgress& s) {
  s.src = gather_sources(s.br, s.g);
  const CompositeField S = s.br.gather_cells([&](Block& b) { return DensitisedStressTrace(b, s.g); });
  s.sv.solve_lapse(s.src.E, S, s.st, s.stats, s.set);
}

// beta, then the solve stored, recorded and logged.
void shift_and_finish(Context& ctx, SolveInProgress& s) {
  s.sv.solve_shift(s.src.E, s.src.S, s.st, s.stats, s.set);
  shift_potentials(ctx, s.potentials);
  store_lapse_shift(s.br, s.g, s.potentials, s.st);
  record_history(ctx);
  warn_unconverged(ctx, s.stats);
  Runtime& rt = runtime(ctx);
  write_tsv(ctx, rt.reason, s.stats, std::chrono::duration<double>(std::chrono::steady_clock::now() - s.t0).count());
  rt.solve.reset();
}

// Initial data given as primitives: iterate psi with the primitives fixed (E~ = psi^6 E changes
// with psi).
void psi_from_primitives(Context& ctx, SolveInProgress& s) {
  const int max_iter = static_cast<int>(ctx.param<std::int64_t>("XCFC", "initial_iterations"));
  double change = 0;
  for (int it = 0; it < max_iter; ++it) {
    conserved_from_primitives(ctx, s.g);
    const Sources src = gather_sources(s.br, s.g);
    const CompositeField old = s.st.psi;
    s.sv.solve_conformal_factor(src.E, src.S, s.st, s.stats, s.set);
    s.br.scatter(s.st.psi, s.g.metric, Metric::idx::psi);
    change = 0;
    for (std::size_t n = 0; n < old.part.size(); ++n)
      for (std::size_t q = 0; q < old.part[n].size(); ++q) change = std::max(change, std::abs(s.st.psi.part[n][q] - old.part[n][q]));
    if (change <= s.set.tolerance) break;
  }
  char m[200];
  std::snprintf(m, sizeof m, "XCFC: initial psi from the primitives, last change %.2e", change);
  ctx.info(m);
  conserved_from_primitives(ctx, s.g);
}

}  // namespace

void step_vector_potential(Context& ctx) {
  Runtime& rt = runtime(ctx);
  if (rt.stage != Stage::solve) return;
  rt.solve = std::make_shared<SolveInProgress>(ctx, false);
  SolveInProgress& s = *rt.solve;
  s.src = gather_sources(s.br, s.g);
  s.sv.solve_vector_potential(s.src.E, s.src.S, s.st, s.stats, s.set);
}

void step_conformal_factor(Context& ctx) {
  SolveInProgress* s = in_progress(ctx);
  if (!s) return;
  s->sv.solve_psi(s->src.E, s->st, s->stats, s->set);
  s->br.scatter(s->st.psi, s->g.metric, Metric::idx::psi);
  runtime(ctx).recovery_due = true;
}

void step_lapse(Context& ctx) {
  if (SolveInProgress* s = in_progress(ctx)) lapse(*s);
}

void step_shift(Context& ctx) {
  SolveInProgress* s = in_progress(ctx);
  if (!s) return;
  shift_and_finish(ctx, *s);
  runtime(ctx).stage = Stage::idle;
}

void initial_conformal_factor(Context& ctx) {
  Runtime& rt = runtime(ctx);
  const std::string& mode = ctx.param<std::string>("XCFC", "initial_metric");
  if (mode == "keep") return;
  rt.reason = "initial";
  rt.solve = std::make_shared<SolveInProgress>(ctx, true);
  SolveInProgress& s = *rt.solve;
  if (mode == "from_primitives") return psi_from_primitives(ctx, s);
  s.src = gather_sources(s.br, s.g);
  s.sv.solve_conformal_factor(s.src.E, s.src.S, s.st, s.stats, s.set);
  s.br.scatter(s.st.psi, s.g.metric, Metric::idx::psi);
  rt.recovery_due = true;
}

void initial_lapse_and_shift(Context& ctx) {
  SolveInProgress* s = in_progress(ctx);
  if (!s) return;
  lapse(*s);
  shift_and_finish(ctx, *s);
}

double psi_residual(Context& ctx) {
  XcfcSolver& sv = solver(ctx);
  const GridBridge br(ctx, sv.multigrid());
  const MatterGroups g = MatterGroups::of(ctx);
  XcfcState st;
  st.psi = br.gather(g.metric, Metric::idx::psi);
  const Sources src = gather_sources(br, g);
  return sv.conformal_factor_residual(src.E, st);
}

}  // namespace remnant::xcfc
