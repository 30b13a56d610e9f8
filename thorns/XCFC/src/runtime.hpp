#pragma once
// XCFC's per-simulation state, published on the Context as the service "XCFC::runtime" (so that
// several simulations in one process, e.g. tests, do not share it). Everything a bit-identical
// continuation needs is either on the grid (Spacetime::metric, XCFC::potentials: the warm starts;
// XCFC::metric_history) or in the persistent counters saved with the checkpoint.
#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "XCFC/xcfc_system.hpp"
#include "adaptive_cadence.hpp"
#include "remnant/context.hpp"

namespace remnant::xcfc {

// One solve in progress between the scheduled steps (solve_sequence.cpp).
struct SolveInProgress;

// What the scheduled steps of XCFC_Solve do in the current pass (cadence.hpp): nothing more
// (idle), a solve, the metric extrapolated in time, the update of psi and alpha psi with the current
// matter between solves (XCFC::update_cycles), or the residual trigger's test.
enum class Stage { idle, solve, extrapolate, update, check_trigger };

struct Runtime {
  Stage stage = Stage::idle;
  const char* reason = "";                 // of the solve, for xcfc.tsv: cadence, residual, initial
  bool recovery_due = false;               // psi changed: the matter thorn recovers the primitives
  bool initial_done = false;               // XCFC_Initial ran its pass
  bool sources_due = false;                // the matter thorn fills Spacetime::matter_sources
  bool initial_sources_taken = false;      // XCFC_InitialMatterSources ran (or was skipped)
  // XCFC::initial_metric = from_primitives: psi iterations done, the last pass, the loop finished.
  struct PsiIteration {
    int count = 0;
    bool final_pass = false, done = false;
  } psi_iteration;
  std::shared_ptr<SolveInProgress> solve;  // between XCFC_VectorPotential and XCFC_Shift
  std::unique_ptr<XcfcSolver> solver;
  CompositeLayout layout;
  std::int64_t steps_since_solve = 0, solves = 0;
  // Times of the last three solves and how many of XCFC::metric_history's three slots are filled.
  double t_last = 0, t_before = 0, t_earlier = 0;
  int history = 0;
  // Steps since the last solve whose psi and alpha psi were updated (XCFC::update_cycles), and the
  // V-cycles they took: logged with the next solve in xcfc.tsv.
  std::int64_t updates = 0, update_cycles = 0;
  // Times of the last two full solves and how many are recorded: X^i's potentials are extrapolated
  // from these (updates keep X^i); without updates they equal t_last, t_before.
  double t_solve_last = 0, t_solve_before = 0;
  int solve_history = 0;
  // A^ij of the last two solves' X potentials, computed at the first update after a solve (for
  // solve count `solves`; rebuilt with the solver). Not checkpointed: recomputed from the same
  // potentials after a restart, so the updates stay bit-identical.
  struct UpdateA {
    std::int64_t solves = -1;
    bool two = false;  // A_before holds the solve before the last
    std::array<CompositeField, 6> last, before;
  } update_A;
  // XCFC::cadence_tolerance: matter steps from the last solve to the next (0: not adapted yet;
  // checkpointed). The last solve's prediction error and the largest of the updates' since the
  // solve before it, for xcfc.tsv.
  std::int64_t interval = 0;
  PredictionError prediction;
  double update_prediction = 0;
  bool tsv_started = false;  // xcfc.tsv created (fresh run) or trimmed (recovered run) by this process
  bool warned_theta = false;
};

// The simulation's runtime, published on first use.
Runtime& runtime(Context& ctx);

// The solver of the current mesh, rebuilt when the forest has changed (a regrid).
XcfcSolver& solver(Context& ctx);

// The persistent counters as text (solve times as hexadecimal floats: a restart extrapolates with
// bit-identical weights) and back; restore throws RunError for text of another form.
std::string save_persistent(const Runtime& rt);
void restore_persistent(Runtime& rt, const std::string& text);

}  // namespace remnant::xcfc
