#include "solve_sequence.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "XCFC/xcfc_system.hpp"
#include "adaptive_cadence.hpp"
#include "cadence.hpp"
#include "grid_bridge.hpp"
#include "remnant/comm_counters.hpp"
#include "remnant/vars/Spacetime.hpp"
#include "remnant/vars/XCFC.hpp"
#include "runtime.hpp"
#include "solve_log.hpp"
#include "update_between_solves.hpp"

namespace remnant::xcfc {
namespace {

using MatterSources = vars::Spacetime::matter_sources;
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

Sources gather_sources(const GridBridge& br, const SpacetimeGroups& g) {
  Sources s;
  s.E = br.gather(g.sources, MatterSources::idx::E);
  for (int d = 0; d < 3; ++d) s.S[d] = br.gather(g.sources, MatterSources::idx::S + d);
  return s;
}

// An update (update = true) stores no X potentials: they stay the last solve's.
void store_lapse_shift(const GridBridge& br, const SpacetimeGroups& g, int potentials, const XcfcState& st, bool update) {
  br.scatter(st.alpha(), g.metric, Metric::idx::alpha);
  for (int d = 0; d < 3; ++d) br.scatter(st.beta[d], g.metric, Metric::idx::beta + d);
  for (int a = 0; a < 3; ++a) {
    if (!update) br.scatter(st.X_potentials.B[a], potentials, Potentials::idx::XB + a);
    br.scatter(st.beta_potentials.B[a], potentials, Potentials::idx::betaB + a);
  }
  if (!update) br.scatter(st.X_potentials.chi, potentials, Potentials::idx::Xchi);
  br.scatter(st.beta_potentials.chi, potentials, Potentials::idx::betachi);
}

}  // namespace

// What every xCFC solve works with, set up from the warm start and kept in the runtime between the
// scheduled steps.
struct SolveInProgress {
  const std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  XcfcSolver& sv;
  const GridBridge br;
  const SpacetimeGroups g;
  const int potentials;
  const SolveSettings set;
  XcfcState st;
  XcfcStats stats;
  Sources src;  // the matter sources of the current step
  const bool update;  // between solves: psi, alpha psi and beta^i, A^ij from the last two solves

  SolveInProgress(Context& ctx, bool initial, bool update_only = false)
      : sv(solver(ctx)), br(ctx, sv.multigrid()), g(SpacetimeGroups::of(ctx)), potentials(ctx.var("XCFC::potentials")),
        set(settings(ctx, initial)), update(update_only) {
    load_warm_start(ctx, br, g, potentials, st, !update_only);
  }
};

namespace {

SolveInProgress* in_progress(Context& ctx) { return runtime(ctx).solve.get(); }

// alpha psi with the final matter (after the recovery: it may have reset cells to atmosphere).
void lapse(SolveInProgress& s) {
  s.src = gather_sources(s.br, s.g);
  const CompositeField S = s.br.gather(s.g.sources, MatterSources::idx::S_trace);
  s.sv.solve_lapse(s.src.E, S, s.st, s.stats, s.set);
}

// beta, then the solve stored, recorded and logged (an update is counted in the next solve's line).
void shift_and_finish(Context& ctx, SolveInProgress& s) {
  s.sv.solve_shift(s.src.E, s.src.S, s.st, s.stats, s.set);
  shift_potentials(ctx, s.potentials, s.update);
  store_lapse_shift(s.br, s.g, s.potentials, s.st, s.update);
  Runtime& rt = runtime(ctx);
  // The metric against what the cadence predicted for now (adaptive_cadence.hpp), before the
  // history takes it; the interval it closes.
  const PredictionError error = prediction_error(ctx);
  const std::int64_t steps = rt.steps_since_solve;
  record_history(ctx, s.update);
  warn_unconverged(ctx, s.stats);
  if (s.update) {
    comm::count_work("xcfc_update", -1, 1);
    ++rt.updates;
    rt.update_cycles += s.stats.psi.cycles + s.stats.alpha_psi.cycles + s.stats.beta.cycles();
    rt.update_prediction = std::max(rt.update_prediction, error.largest());
    rt.solve.reset();
    return;
  }
  rt.prediction = error;
  comm::count_work("xcfc_solve", -1, 1);
  write_tsv(ctx, rt.reason, s.stats, steps, std::chrono::duration<double>(std::chrono::steady_clock::now() - s.t0).count());
  adapt_interval(ctx, steps, error);
  rt.updates = rt.update_cycles = 0, rt.update_prediction = 0;  // logged with this solve
  rt.solve.reset();
}

}  // namespace

void step_vector_potential(Context& ctx) {
  Runtime& rt = runtime(ctx);
  if (rt.stage == Stage::update) {
    // Between solves: A^ij extrapolated from the last two solves' X^i, no V-cycle; psi, alpha psi
    // and beta^i follow in the steps below.
    rt.solve = std::make_shared<SolveInProgress>(ctx, false, true);
    SolveInProgress& s = *rt.solve;
    s.src = gather_sources(s.br, s.g);
    load_update_A(ctx, s.br, s.sv, s.st);
    for (SolveStats& c : s.stats.X.component) c.converged = true;  // nothing solved: nothing to warn of
    s.stats.X.chi.converged = true;
    return;
  }
  if (rt.stage != Stage::solve) return;
  rt.solve = std::make_shared<SolveInProgress>(ctx, false);
  SolveInProgress& s = *rt.solve;
  s.src = gather_sources(s.br, s.g);
  s.sv.solve_vector_potential(s.src.E, s.src.S, s.st, s.stats, s.set);
  // X^i served only A^ij (its potentials are the warm start, kept): freed for the later steps
  // (issue 21, memory: three composite fields fewer at the shift solve's peak).
  for (CompositeField& x : s.st.X) x = CompositeField{};
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
  const bool update = s->update;
  shift_and_finish(ctx, *s);
  // After an update the residual trigger may still ask for a solve.
  runtime(ctx).stage = update ? Stage::check_trigger : Stage::idle;
}

void initial_conformal_factor(Context& ctx) {
  Runtime& rt = runtime(ctx);
  if (ctx.param<std::string>("XCFC", "initial_metric") != "from_conserved") return;
  rt.reason = "initial";
  rt.solve = std::make_shared<SolveInProgress>(ctx, true);
  SolveInProgress& s = *rt.solve;
  s.src = gather_sources(s.br, s.g);
  s.sv.solve_conformal_factor(s.src.E, s.src.S, s.st, s.stats, s.set);
  s.br.scatter(s.st.psi, s.g.metric, Metric::idx::psi);
  rt.recovery_due = true;
}

// Initial data given as primitives: psi iterated with the primitives fixed (E~ = psi^6 E changes
// with psi). Each pass of XCFC_InitialPsiFromPrimitives: the matter thorn makes the conserved
// variables and sources of the primitives with the current psi, then one psi solve here; after the
// last change below the tolerance (or XCFC::initial_iterations), one more pass for the final psi.
void initial_psi_iteration(Context& ctx) {
  Runtime& rt = runtime(ctx);
  if (rt.psi_iteration.final_pass) {
    rt.psi_iteration.done = true;
    return;
  }
  if (!rt.solve) rt.reason = "initial", rt.solve = std::make_shared<SolveInProgress>(ctx, true);
  SolveInProgress& s = *rt.solve;
  const Sources src = gather_sources(s.br, s.g);
  const CompositeField old = s.st.psi;
  s.sv.solve_conformal_factor(src.E, src.S, s.st, s.stats, s.set);
  s.br.scatter(s.st.psi, s.g.metric, Metric::idx::psi);
  double change = 0;
  for (std::size_t n = 0; n < old.part.size(); ++n)
    for (std::size_t q = 0; q < old.part[n].size(); ++q) change = std::max(change, std::abs(s.st.psi.part[n][q] - old.part[n][q]));
  const int max_iter = static_cast<int>(ctx.param<std::int64_t>("XCFC", "initial_iterations"));
  if (change <= s.set.tolerance || ++rt.psi_iteration.count >= max_iter) {
    rt.psi_iteration.final_pass = true;
    char m[200];
    std::snprintf(m, sizeof m, "XCFC: initial psi from the primitives, last change %.2e", change);
    ctx.info(m);
  }
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
  const SpacetimeGroups g = SpacetimeGroups::of(ctx);
  XcfcState st;
  st.psi = br.gather(g.metric, Metric::idx::psi);
  const Sources src = gather_sources(br, g);
  return sv.conformal_factor_residual(src.E, st);
}

}  // namespace remnant::xcfc
