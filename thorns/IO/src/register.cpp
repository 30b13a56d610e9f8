// IO: binds the TSV, HDF5 and checkpoint code to the schedule (see thorn.yaml).
#include <memory>
#include <sstream>

#include "checkpoint.hpp"
#include "checkpoint_files.hpp"
#include "grid_output.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "tsv_output.hpp"

namespace remnant::io {
namespace {

struct State {
  std::vector<TsvSeries> series;
  bool tsv_started = false;
  GridOutputPlan grid;
  CheckpointSettings checkpoint;
  std::int64_t last_checkpoint_iteration = -1;
  double last_checkpoint_wall = 0;
  StepHistory steps;
};

State& state(Context& ctx) {
  if (!ctx.has_service("IO::state")) ctx.publish("IO::state", std::make_shared<State>());
  return ctx.service<State>("IO::state");
}

std::array<double, 3> point(const Context& ctx, const char* name) {
  const auto& v = ctx.param<std::vector<double>>("IO", name);
  return {v[0], v[1], v[2]};
}

// Could this run write a checkpoint? Then its folder must be usable before any output is written.
bool checkpoints_possible(const Context& ctx) {
  bool wall_end = false;
  for (const auto& t : ctx.active_thorns())
    if (t == "MoL") wall_end = ctx.param<double>("MoL", "max_walltime_hours") > 0;
  return ctx.param<std::int64_t>("IO", "checkpoint_every") > 0 ||
         ctx.param<double>("IO", "checkpoint_every_walltime_hours") > 0 || ctx.param<bool>("IO", "checkpoint_on_terminate") ||
         wall_end;
}

// Rank 0 creates the folder and a probe file in it; every rank throws the same InputError.
void check_checkpoint_dir(const Context& ctx, const std::string& dir) {
  std::string why = ctx.rank() == 0 ? writable_folder_problem(dir) : std::string();
  int len = static_cast<int>(why.size());
  MPI_Bcast(&len, 1, MPI_INT, 0, ctx.comm());
  why.resize(static_cast<std::size_t>(len));
  MPI_Bcast(why.data(), len, MPI_CHAR, 0, ctx.comm());
  if (!why.empty())
    throw InputError(ctx.params().origin("IO", "checkpoint_dir"),
                     "IO::checkpoint_dir: checkpoints cannot be written to '" + dir + "': " + why +
                         "; set IO::checkpoint_dir to a writable folder (empty: <Flesh::out_dir>/checkpoints)");
}

void check_parameters(Context& ctx) {
  State& s = state(ctx);
  s.series = plan_tsv_series(ctx, ctx.param<std::vector<std::string>>("IO", "tsv_variables"),
                             ctx.param<std::vector<std::string>>("IO", "tsv_reductions"));
  GridOutputPlan& g = s.grid;
  g.variables = resolve_variables(ctx, "hdf5_variables", ctx.param<std::vector<std::string>>("IO", "hdf5_variables"));
  for (auto& v : g.variables) {
    // Face groups are written as cell averages of their two faces (checkpoints keep raw faces).
    const Centering c = ctx.vars().group(v.group).centering;
    const int face = c == Centering::face_x ? 0 : c == Centering::face_y ? 1 : c == Centering::face_z ? 2 : -1;
    if (c != Centering::cell && face < 0)
      throw InputError(ctx.params().origin("IO", "hdf5_variables"),
                       "IO::hdf5_variables: " + v.full + " is " + to_string(c) +
                           "-centred; grid output writes cell- and face-centred groups (faces as cell averages)");
    if (face >= 0 && (!ctx.has_grid() || face < ctx.grid().dimension())) {
      v.average_direction = face;
      v.centering_note = std::string("cell average of ") + to_string(c);
    }
  }
  g.outputs = ctx.param<std::vector<std::string>>("IO", "hdf5_output");
  g.point = point(ctx, "slice_point");
  g.xdmf = ctx.param<bool>("IO", "hdf5_xdmf");
  g.every = ctx.param<std::int64_t>("IO", "hdf5_every");
  g.every_time = ctx.param<double>("IO", "hdf5_every_time");
  if (!g.variables.empty() && g.every == 0 && g.every_time == 0)
    ctx.warn("IO::hdf5_variables is set but IO::hdf5_every and IO::hdf5_every_time are 0: no HDF5 output");
  if (ctx.has_grid())
    for (const auto& o : g.outputs) {
      try {
        make_cut(o, ctx.grid().dimension(), g.point);
      } catch (const RunError& e) {
        throw InputError(ctx.params().origin("IO", "hdf5_output"), e.what());
      }
    }
  const std::string& dir = ctx.param<std::string>("IO", "checkpoint_dir");
  s.checkpoint.dir = dir.empty() ? ctx.out_dir() + "/checkpoints" : dir;
  s.checkpoint.keep = static_cast<int>(ctx.param<std::int64_t>("IO", "checkpoint_keep"));
  s.checkpoint.kill_at_iteration = ctx.param<std::int64_t>("IO", "test_kill_at_checkpoint");
  if (checkpoints_possible(ctx)) check_checkpoint_dir(ctx, s.checkpoint.dir);
  s.last_checkpoint_wall = MPI_Wtime();
  const std::string& recover = ctx.param<std::string>("IO", "recover");
  if (recover.empty())
    throw InputError(ctx.params().origin("IO", "recover"), "IO::recover: empty; use no, auto or the path of a checkpoint file");
}

bool recover(Context& ctx) {
  State& s = state(ctx);
  std::string used;
  if (!recover_checkpoint(ctx, ctx.param<std::string>("IO", "recover"), s.checkpoint, &used, &s.steps)) return false;
  // Outputs after the recovered iteration came from a run that died later: drop them, so that a
  // restarted run leaves the same files as an uninterrupted one.
  resume_tsv_files(s.series, ctx, ctx.iteration());
  s.tsv_started = true;
  forget_grid_outputs_after(s.grid, ctx, ctx.iteration());
  s.last_checkpoint_iteration = ctx.iteration();
  return true;
}

void write_tsv(Context& ctx) {
  const auto every = ctx.param<std::int64_t>("IO", "tsv_every");
  if (every <= 0 || ctx.iteration() % every != 0) return;
  State& s = state(ctx);
  if (!s.tsv_started) {
    start_tsv_files(s.series, ctx);
    s.tsv_started = true;
  }
  append_tsv_lines(s.series, ctx, point(ctx, "centre"));
}

void write_hdf5(Context& ctx) {
  State& s = state(ctx);
  if (grid_output_due(s.grid, ctx)) write_grid_outputs(s.grid, ctx);
}

void checkpoint_now(Context& ctx, State& s) {
  write_checkpoint(ctx, s.checkpoint, s.steps);
  s.last_checkpoint_iteration = ctx.iteration();
  s.last_checkpoint_wall = MPI_Wtime();
}

void checkpoint(Context& ctx) {
  State& s = state(ctx);
  s.steps.observe(ctx.dt());  // this bin runs once after every step
  const auto every = ctx.param<std::int64_t>("IO", "checkpoint_every");
  bool due = every > 0 && ctx.iteration() % every == 0;
  const double hours = ctx.param<double>("IO", "checkpoint_every_walltime_hours");
  if (hours > 0) {
    // Rank 0's clock decides for everyone: ranks must agree on a collective write.
    int wall_due = (MPI_Wtime() - s.last_checkpoint_wall) / 3600.0 >= hours ? 1 : 0;
    MPI_Bcast(&wall_due, 1, MPI_INT, 0, ctx.comm());
    due = due || wall_due;
  }
  if (due && s.last_checkpoint_iteration != ctx.iteration()) checkpoint_now(ctx, s);
}

void terminate(Context& ctx) {
  State& s = state(ctx);
  const bool walltime = ctx.termination_reason().find("max_walltime_hours") != std::string::npos;
  if ((walltime || ctx.param<bool>("IO", "checkpoint_on_terminate")) && ctx.has_grid() &&
      s.last_checkpoint_iteration != ctx.iteration()) {
    if (walltime) ctx.info("wall-clock limit: writing a final checkpoint");
    checkpoint_now(ctx, s);
  }
  for (const auto& t : s.series)
    if (t.nan_rows > 0) ctx.warn(t.path + ": " + std::to_string(t.nan_rows) + " rows hold NaN");
}

// IO's own continuation state: the last multiple of hdf5_every_time written.
std::string save_state(Context& ctx) { return std::to_string(state(ctx).grid.last_time_index); }
void restore_state(Context& ctx, const std::string& text) { state(ctx).grid.last_time_index = std::stoll(text); }

}  // namespace
}  // namespace remnant::io

REMNANT_REGISTER_THORN(IO) {
  using namespace remnant::io;
  reg.function("IO_CheckParameters", check_parameters);
  reg.function("IO_WriteTSV", write_tsv);
  reg.function("IO_WriteHDF5", write_hdf5);
  reg.function("IO_Checkpoint", checkpoint);
  reg.function("IO_Terminate", terminate);
  reg.recovery(recover);
  reg.persistent_state(save_state, restore_state);
}
