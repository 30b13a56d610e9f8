// MoL: Runge-Kutta substeps over every evolved group, the CFL time step and the end of the run.
#include <mpi.h>

#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "runge_kutta.hpp"
#include "step_start_copy.hpp"

namespace remnant::mol {
namespace {

// Per-simulation state, published as a service so that several simulations in one process
// (tests) do not share it.
struct State {
  const std::vector<RungeKuttaStage>* stages = nullptr;
  std::size_t next_stage = 0;
  double t0 = 0;
  double wall_start = 0;
  // Every evolved group's interior at the start of the step, per local block.
  StepStartCopy u0;
  std::int64_t first_iteration = -1;    // of this process's run (a recovered run starts later)
  bool warned_dt = false;
  // Published as service "failure_hint": the driver adds it to a fatal error's message.
  std::shared_ptr<std::string> failure_hint = std::make_shared<std::string>();
};

// Largest stable Courant number dt * max(signal speed / cell width) of each method: SSP-RK3,
// SSP-RK2 and forward Euler all have SSP coefficient 1, so they keep a scheme that is stable with
// forward Euler at Courant number 1 stable up to 1 (the thorns' CFL limits are defined that way).
constexpr double kStableCourant = 1.0;

State& state(Context& ctx) {
  if (!ctx.has_service("MoL::state")) {
    auto s = std::make_shared<State>();
    s->stages = &runge_kutta_stages(ctx.param<std::string>("MoL", "method"));
    s->wall_start = MPI_Wtime();
    ctx.publish("MoL::state", s);
    ctx.publish("failure_hint", s->failure_hint);
  }
  return ctx.service<State>("MoL::state");
}

void check_parameters(Context& ctx) {
  state(ctx);
  const double final_time = ctx.param<double>("MoL", "final_time");
  const auto max_it = ctx.param<std::int64_t>("MoL", "max_iterations");
  const double max_wall = ctx.param<double>("MoL", "max_walltime_hours");
  if (final_time < 0 && max_it < 0 && max_wall <= 0)
    throw InputError(ctx.params().origin("MoL", "final_time"),
                     "the run would never end: set MoL::final_time, MoL::max_iterations or MoL::max_walltime_hours");
  if (ctx.vars().evolved().empty()) ctx.warn("no active thorn declares an evolved variable group: nothing to integrate");
  const double cfl = ctx.param<double>("MoL", "cfl");
  if (ctx.param<double>("MoL", "dt") <= 0 && cfl > kStableCourant && ctx.rank() == 0) {
    std::ostringstream os;
    os << "MoL::cfl = " << cfl << " is above the stability limit " << kStableCourant
       << " of MoL::method = " << ctx.param<std::string>("MoL", "method")
       << ": the time step is too large and the run will likely blow up (the default is 0.4)";
    ctx.warn(os.str());
  }
}

// For the first steps of a fixed MoL::dt, and for every step from the CFL condition: the Courant
// number of the step, a warning when it is above the stability limit, and the hint the driver adds
// to an error (a failed primitive recovery is the usual symptom of a too large time step).
void check_courant_number(Context& ctx, State& s, double dt, double inv, bool fixed) {
  const double courant = dt * inv;
  std::string& hint = *s.failure_hint;
  if (!(courant > kStableCourant)) {
    hint.clear();
    return;
  }
  std::ostringstream os;
  os << "the time step dt = " << dt << " is " << courant / kStableCourant << " times the largest stable one ("
     << kStableCourant / inv << ", Courant number " << kStableCourant << " of MoL::method = "
     << ctx.param<std::string>("MoL", "method") << "): lower " << (fixed ? "MoL::dt" : "MoL::cfl");
  hint = os.str();
  if (fixed && !s.warned_dt && ctx.rank() == 0) ctx.warn(hint);
  s.warned_dt = true;
}

void compute_time_step(Context& ctx) {
  State& s = state(ctx);
  if (s.first_iteration < 0) s.first_iteration = ctx.iteration();
  const double fixed = ctx.param<double>("MoL", "dt");
  double dt = fixed, inv = 0;
  if (dt <= 0) {
    inv = ctx.max_inverse_dt();
    if (!(inv > 0) || !std::isfinite(inv))
      throw RunError("no thorn limits the time step (max 1/dt = " + std::to_string(inv) + "); set MoL::dt");
    dt = ctx.param<double>("MoL", "cfl") / inv;
  } else if (ctx.iteration() - s.first_iteration < 3) {
    // A fixed step is compared with the CFL limit in the first steps only (the limit costs a pass).
    inv = ctx.max_inverse_dt();
  }
  // Land exactly on final_time so that outputs at the end are comparable between resolutions.
  const double final_time = ctx.param<double>("MoL", "final_time");
  if (final_time >= 0 && ctx.time() + dt > final_time) dt = final_time - ctx.time();
  if (inv > 0 && std::isfinite(inv)) check_courant_number(ctx, s, dt, inv, fixed > 0);
  ctx.clock().dt = dt;
}

bool next_substep(Context& ctx) {
  State& s = state(ctx);
  auto& clock = ctx.clock();
  if (s.next_stage == 0) {
    s.t0 = clock.time;
    s.u0.save(ctx.grid().local_blocks(), ctx.vars().evolved(), ctx.vars());
  }
  if (s.next_stage == s.stages->size()) {
    s.next_stage = 0;
    clock.substep = 0;
    clock.time = s.t0 + clock.dt;
    return false;
  }
  clock.substep = static_cast<int>(s.next_stage);
  clock.time = s.t0 + (*s.stages)[s.next_stage].c * clock.dt;
  return true;
}

void update(Context& ctx) {
  State& s = state(ctx);
  const std::size_t stage = s.next_stage;
  const RungeKuttaStage& st = (*s.stages)[stage];
  const double dt = ctx.dt();
  for (Block* b : ctx.grid().local_blocks())
    for (int g : ctx.vars().evolved()) {
      const auto& spec = ctx.vars().group(g);
      // Interior points: cells, and for face groups the faces of the interior, both block faces
      // included (n + 1 along a used staggered direction).
      const auto points = interior_points(*b, spec.centering);
      // Face fields (constrained transport) in increment form: see runge_kutta_increment_update.
      const bool increment = spec.centering != Centering::cell && st.a + st.b == 1.0;
      for (int c = 0; c < spec.ncomp(); ++c) {
        Field u = b->field(g, c);
        Field rhs = b->field(spec.rhs_id, c);
        // Interior rows are contiguous in i: update row by row.
        for (int k = 0; k < points[2]; ++k)
          for (int j = 0; j < points[1]; ++j) {
            double* urow = &u(0, j, k);
            const double* rrow = &rhs(0, j, k);
            const double* u0row = s.u0.row(b->gid, g, c, j, k);
            if (increment)
              runge_kutta_increment_update(urow, u0row, rrow, static_cast<std::size_t>(points[0]), st.b, dt);
            else
              runge_kutta_update(urow, u0row, rrow, static_cast<std::size_t>(points[0]), st.a, st.b, dt);
          }
      }
    }
  ++s.next_stage;
  // The new state lives at t0 + (time after this stage) dt: post-step functions see that time.
  ctx.clock().time = s.t0 + time_after_stage(*s.stages, stage) * dt;
}

std::string termination(Context& ctx) {
  const double final_time = ctx.param<double>("MoL", "final_time");
  const auto max_it = ctx.param<std::int64_t>("MoL", "max_iterations");
  const double max_wall = ctx.param<double>("MoL", "max_walltime_hours");
  std::ostringstream why;
  if (max_it >= 0 && ctx.iteration() >= max_it) {
    why << "reached MoL::max_iterations = " << max_it;
  } else if (final_time >= 0 && ctx.time() >= final_time * (1 - 1e-14)) {
    why << "reached MoL::final_time = " << final_time;
  } else if (max_wall > 0 && (MPI_Wtime() - state(ctx).wall_start) / 3600.0 >= max_wall) {
    why << "reached MoL::max_walltime_hours = " << max_wall;
  }
  return why.str();
}

double progress(Context& ctx) {
  const double final_time = ctx.param<double>("MoL", "final_time");
  const auto max_it = ctx.param<std::int64_t>("MoL", "max_iterations");
  double f = 0;
  if (final_time > 0) f = std::max(f, ctx.time() / final_time);
  if (max_it > 0) f = std::max(f, static_cast<double>(ctx.iteration()) / static_cast<double>(max_it));
  return std::min(f, 1.0);
}

}  // namespace
}  // namespace remnant::mol

REMNANT_REGISTER_THORN(MoL) {
  using namespace remnant::mol;
  reg.function("MoL_CheckParameters", check_parameters);
  reg.function("MoL_ComputeTimeStep", compute_time_step);
  reg.predicate("MoL_NextSubstep", next_substep);
  reg.function("MoL_Update", update);
  reg.termination_check(termination);
  reg.progress_fraction(progress);
}
