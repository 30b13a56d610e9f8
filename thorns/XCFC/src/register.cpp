// XCFC: binds the scheduled functions of thorn.yaml. The sequence per solve (paper's order):
// X^i -> A^ij -> psi -> con2prim with the new psi -> alpha psi -> beta^i; the metric goes to
// Spacetime::metric (GRMHD interpolates it to faces in each RHS evaluation).
#include <mpi.h>

#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>

#include "XCFC/xcfc_system.hpp"
#include "grid_bridge.hpp"
#include "matter_coupling.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "remnant/tsv_file.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::xcfc {
namespace {

// Kept between calls; everything a bit-identical continuation needs is either on the grid
// (Spacetime::metric, XCFC::potentials: the warm starts) or in the persistent counters.
struct Runtime {
  std::unique_ptr<XcfcSolver> solver;
  CompositeLayout layout;
  std::int64_t steps_since_solve = 0, solves = 0;
  // Times of the last two solves and how many of XCFC::metric_history's two slots are filled.
  double t_last = 0, t_before = 0;
  int history = 0;
  bool tsv_started = false;  // xcfc.tsv created (fresh run) or trimmed (recovered run) by this process
  bool warned_theta = false;
};

Runtime& runtime() {
  static Runtime r;
  return r;
}

bool same_layout(const CompositeLayout& a, const CompositeLayout& b) {
  return a.base.n == b.base.n && a.base.coordinates == b.base.coordinates && a.base.dimension == b.base.dimension &&
         a.base.lo == b.base.lo && a.base.dx == b.base.dx && a.patch_cells == b.patch_cells && a.patches == b.patches;
}

// A refined level whose blocks at the spherical origin do not span every theta (and phi in 3D): the
// composite V-cycle then converges slowly (README, "Refined grids"); returns the first such level
// or 0.
int level_ending_in_theta_at_origin(const CompositeLayout& lay) {
  const GridShape& b = lay.base;
  if (b.coordinates != CoordinateSystem::spherical || b.dimension < 2 || b.boundary[0][0] != Boundary::origin) return 0;
  // Cells of the (theta[, phi]) surface that level l + 1's patches at r = 0 cover, against all.
  const bool three = b.dimension == 3;
  for (std::size_t l = 0; l < lay.patches.size(); ++l) {
    long long covered = 0;
    for (const auto& c : lay.patches[l])
      if (c[0] == 0) covered += static_cast<long long>(lay.patch_cells[1]) * (three ? lay.patch_cells[2] : 1);
    const long long all = (static_cast<long long>(b.n[1]) << (l + 1)) * (three ? static_cast<long long>(b.n[2]) << (l + 1) : 1);
    if (covered > 0 && covered < all) return static_cast<int>(l) + 1;
  }
  return 0;
}

// The solver of the current mesh, rebuilt when the forest has changed (a regrid).
XcfcSolver& solver(Context& ctx) {
  Runtime& rt = runtime();
  CompositeLayout lay = layout_of_grid(ctx);
  if (!rt.solver || !same_layout(lay, rt.layout)) {
    if (const int l = level_ending_in_theta_at_origin(lay); l > 0 && !rt.warned_theta)
      ctx.warn("XCFC: refinement level " + std::to_string(l) +
               " ends in theta (or phi) next to the spherical origin; the composite metric solve converges slowly there "
               "(refine all theta near the origin, e.g. with a Grid::regions sphere; thorns/XCFC/README.md)"),
          rt.warned_theta = true;
    rt.layout = lay;
    // The base level's cycles are split between the ranks; patches are computed by every rank.
    rt.solver = lay.patches.empty() ? std::make_unique<XcfcSolver>(lay.base, ctx.grid().comm())
                                    : std::make_unique<XcfcSolver>(lay, ctx.grid().comm());
  }
  return *rt.solver;
}

SolveSettings settings(const Context& ctx, bool initial) {
  SolveSettings s;
  s.tolerance = ctx.param<double>("XCFC", initial ? "tolerance_initial" : "tolerance");
  s.max_cycles = static_cast<int>(ctx.param<std::int64_t>("XCFC", "max_cycles"));
  s.pre_sweeps = s.post_sweeps = static_cast<int>(ctx.param<std::int64_t>("XCFC", "sweeps"));
  s.full_multigrid = initial;
  return s;
}

// Warm starts and the groups of one solve.
struct Sources {
  CompositeField E;
  VectorField S;
};

Sources gather_sources(const GridBridge& br, const MatterGroups& g) {
  Sources s;
  using Cons = vars::HydroBase::cons;
  s.E = br.gather_cells([&](Block& b) {
    const Cons cons(b, g.cons);
    const Field D = cons.field(Cons::idx::D), tau = cons.field(Cons::idx::tau);
    return [=](int i, int j, int k) { return D(i, j, k) + tau(i, j, k); };
  });
  for (int d = 0; d < 3; ++d) s.S[d] = br.gather(g.cons, Cons::idx::S + d);
  return s;
}

// The warm starts: the last solve's psi, alpha psi and potentials, or, once two solves are recorded,
// their linear extrapolation in time to now (w = (t - t_last) / (t_last - t_before)): the change
// between solves is then left to second order, which saves V-cycles (README, "Cadence").
// The weight w of last + w (last - before) at the current time, or none before two solves.
std::optional<double> extrapolation_weight(const Context& ctx) {
  const Runtime& rt = runtime();
  if (rt.history < 2 || !(rt.t_last > rt.t_before)) return std::nullopt;
  return (ctx.time() - rt.t_last) / (rt.t_last - rt.t_before);
}

void load_warm_start(Context& ctx, const GridBridge& br, const MatterGroups& g, int potentials, XcfcState& st) {
  const std::optional<double> weight = extrapolation_weight(ctx);
  const bool extrapolate = weight && *weight > 0;
  const double w = extrapolate ? *weight : 0.0;
  const int hist = ctx.var("XCFC::metric_history"), before = ctx.var("XCFC::potentials_before");
  // last + w (last - before) of two fields of a block, per cell.
  auto extrapolated = [w](Field last, Field prev) {
    return [=](int i, int j, int k) { return last(i, j, k) + w * (last(i, j, k) - prev(i, j, k)); };
  };
  if (extrapolate) {
    st.psi = br.gather_cells([&](Block& b) { return extrapolated(b.field(hist, 0), b.field(hist, 5)); });
    st.alpha_psi = br.gather_cells([&](Block& b) {
      const auto psi = extrapolated(b.field(hist, 0), b.field(hist, 5)), alpha = extrapolated(b.field(hist, 1), b.field(hist, 6));
      return [=](int i, int j, int k) { return psi(i, j, k) * alpha(i, j, k); };
    });
  } else {
    st.psi = br.gather(g.metric, 0);
    st.alpha_psi = br.gather_cells([&](Block& b) {
      const Field psi = b.field(g.metric, 0), alpha = b.field(g.metric, 1);
      return [=](int i, int j, int k) { return psi(i, j, k) * alpha(i, j, k); };
    });
  }
  auto potential = [&](int c) {
    if (!extrapolate) return br.gather(potentials, c);
    return br.gather_cells([&](Block& b) { return extrapolated(b.field(potentials, c), b.field(before, c)); });
  };
  for (int a = 0; a < 3; ++a) {
    st.X_potentials.B[a] = potential(a);
    st.beta_potentials.B[a] = potential(4 + a);
  }
  st.X_potentials.chi = potential(3);
  st.beta_potentials.chi = potential(7);
}

// XCFC::potentials (the last solve's) -> XCFC::potentials_before, before the new ones are stored.
void shift_potentials(Context& ctx, int potentials) {
  const int before = ctx.var("XCFC::potentials_before");
  for (Block* b : ctx.grid().local_blocks())
    for (int c = 0; c < 8; ++c) {
      Field p = b->field(potentials, c), q = b->field(before, c);
      for_interior(*b, [&](int i, int j, int k) { q(i, j, k) = p(i, j, k); });
    }
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

void check_fatal(Context& ctx, std::uint64_t fatal) {
  std::uint64_t total = 0;
  MPI_Allreduce(&fatal, &total, 1, MPI_UINT64_T, MPI_SUM, ctx.comm());
  if (total > 0) throw RunError("XCFC: a fatal error-policy rule fired in " + std::to_string(total) + " cells in the recovery with the new psi");
}

void write_tsv(Context& ctx, const char* reason, const XcfcStats& s, double seconds) {
  if (ctx.rank() != 0) return;
  const std::string path = ctx.out_dir() + "/xcfc.tsv";
  if (!runtime().tsv_started)
    start_or_resume_tsv_file(ctx, path,
                             "# iteration\ttime\treason\tX_cycles\tX_residual\tpsi_cycles\tpsi_residual\talphapsi_cycles\t"
                             "alphapsi_residual\tbeta_cycles\tbeta_residual\twall_s\n",
                             RowTime::before_step);  // a prestep row of iteration n follows n's checkpoint
  runtime().tsv_started = true;
  std::ofstream out(path, std::ios::app);
  auto rel = [](const SolveStats& x) { return x.scale > 0 ? x.residual / x.scale : x.residual; };
  char line[512];
  std::snprintf(line, sizeof line, "%lld\t%.17g\t%s\t%d\t%.3e\t%d\t%.3e\t%d\t%.3e\t%d\t%.3e\t%.6f\n",
                static_cast<long long>(ctx.iteration()), ctx.time(), reason, s.X.cycles(), s.X.residual(), s.psi.cycles,
                rel(s.psi), s.alpha_psi.cycles, rel(s.alpha_psi), s.beta.cycles(), s.beta.residual(), seconds);
  out << line;
}

void warn_unconverged(Context& ctx, const XcfcStats& s) {
  if (!(s.X.converged() && s.psi.converged && s.alpha_psi.converged && s.beta.converged()))
    ctx.warn("XCFC: a metric solve reached XCFC::max_cycles before the tolerance (see xcfc.tsv)");
}

// Shifts XCFC::metric_history (last -> before) and stores the metric just solved as the last.
void record_history(Context& ctx) {
  Runtime& rt = runtime();
  const int metric = ctx.var("Spacetime::metric"), hist = ctx.var("XCFC::metric_history");
  for (Block* b : ctx.grid().local_blocks())
    for (int c = 0; c < 5; ++c) {
      Field m = b->field(metric, c), last = b->field(hist, c), before = b->field(hist, 5 + c);
      // The first solve fills both slots: "before" is unused until a second solve is recorded,
      // but it is declared written (and checkpointed), so it must hold defined values.
      const Field& previous = rt.history == 0 ? m : last;
      for_interior(*b, [&](int i, int j, int k) {
        before(i, j, k) = previous(i, j, k);
        last(i, j, k) = m(i, j, k);
      });
    }
  rt.t_before = rt.t_last;
  rt.t_last = ctx.time();
  rt.history = std::min(rt.history + 1, 2);
}

// Between solves: the metric at the current time extrapolated linearly from the last two solves,
// then the primitives recovered with the new psi (the densitised conserved variables are the
// evolved ones). Holding the metric instead lags gravity by half a solve interval on average, which
// acts as a damping force on the stellar oscillations (README, "Cadence").
void extrapolate(Context& ctx) {
  const std::optional<double> weight = extrapolation_weight(ctx);
  if (!weight) return;
  const double w = *weight;
  const int metric = ctx.var("Spacetime::metric"), hist = ctx.var("XCFC::metric_history");
  for (Block* b : ctx.grid().local_blocks())
    for (int c = 0; c < 5; ++c) {
      Field m = b->field(metric, c), last = b->field(hist, c), before = b->field(hist, 5 + c);
      for_interior(*b, [&](int i, int j, int k) { m(i, j, k) = last(i, j, k) + w * (last(i, j, k) - before(i, j, k)); });
    }
  check_fatal(ctx, recover_primitives(ctx, MatterGroups::of(ctx)));
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
    ++runtime().solves;
    runtime().steps_since_solve = 0;
    warn_unconverged(ctx, stats);
    write_tsv(ctx, reason, stats, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
};

// One xCFC solve with the densitised conserved variables held fixed (evolution and hand-off).
void solve_sequence(Context& ctx, bool initial, const char* reason) {
  Solve s(ctx, initial);
  const Sources src = gather_sources(s.br, s.g);
  s.sv.solve_conformal_factor(src.E, src.S, s.st, s.stats, s.set);
  s.br.scatter(s.st.psi, s.g.metric, 0);
  check_fatal(ctx, recover_primitives(ctx, s.g));
  s.finish(ctx, gather_sources(s.br, s.g), reason);  // the recovery may have reset cells to atmosphere
}

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

void initial(Context& ctx) {
  runtime() = Runtime{};
  const std::string& mode = ctx.param<std::string>("XCFC", "initial_metric");
  if (mode == "from_primitives") solve_from_primitives(ctx);
  else if (mode == "from_conserved") solve_sequence(ctx, true, "initial");
}

// Relative residual of the psi equation with the current matter (A^2 term left out: it is not
// stored between solves, and its contribution is second order in the velocities).
double psi_residual(Context& ctx) {
  XcfcSolver& sv = solver(ctx);
  const GridBridge br(ctx, sv.multigrid());
  const MatterGroups g = MatterGroups::of(ctx);
  XcfcState st;
  st.psi = br.gather(g.metric, 0);
  const Sources src = gather_sources(br, g);
  return sv.conformal_factor_residual(src.E, st);
}

void prestep(Context& ctx) {
  Runtime& rt = runtime();
  const std::int64_t every = ctx.param<std::int64_t>("XCFC", "solve_every");
  if (every <= 0) return;
  ++rt.steps_since_solve;
  if (rt.steps_since_solve >= every) return solve_sequence(ctx, false, "cadence");
  if (ctx.param<std::string>("XCFC", "extrapolation") == "linear") extrapolate(ctx);
  const double trigger = ctx.param<double>("XCFC", "residual_trigger");
  if (trigger > 0 && psi_residual(ctx) > trigger) solve_sequence(ctx, false, "residual");
}

// Before anything is computed: the Grid's boundaries must be ones the solver knows.
void check_parameters(Context& ctx) {
  const int dim = ctx.grid().dimension();
  const CoordinateSystem cs = ctx.grid().coordinates();
  const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& hi = ctx.param<std::vector<double>>("Grid", "xmax");
  for (const char* side : {"boundary_lower", "boundary_upper"}) {
    const auto& names = ctx.param<std::vector<std::string>>("Grid", side);
    for (int d = 0; d < dim; ++d) {
      const auto u = static_cast<std::size_t>(d);
      try {
        (void)boundary_kind(names[u], d, cs, hi[u] - lo[u]);
      } catch (const std::invalid_argument& e) {
        throw InputError(ctx.params().origin("Grid", side), e.what());
      }
    }
  }
}

}  // namespace
}  // namespace remnant::xcfc

REMNANT_REGISTER_THORN(XCFC) {
  using namespace remnant::xcfc;
  reg.function("XCFC_CheckParameters", check_parameters);
  reg.function("XCFC_Initial", initial);
  reg.function("XCFC_Solve", prestep);
  reg.persistent_state(
      [](remnant::Context&) {
        // Solve times as hexadecimal floats: a restart extrapolates with bit-identical weights.
        const Runtime& rt = runtime();
        char text[160];
        std::snprintf(text, sizeof text, "%lld %lld %a %a %d", static_cast<long long>(rt.steps_since_solve),
                      static_cast<long long>(rt.solves), rt.t_last, rt.t_before, rt.history);
        return std::string(text);
      },
      [](remnant::Context&, const std::string& text) {
        Runtime& rt = runtime();
        std::istringstream s(text);
        std::string t_last, t_before;
        s >> rt.steps_since_solve >> rt.solves >> t_last >> t_before >> rt.history;
        if (!s) throw remnant::RunError("XCFC: the checkpoint's persistent state '" + text + "' is not 'steps solves t_last t_before history'");
        rt.t_last = std::strtod(t_last.c_str(), nullptr);
        rt.t_before = std::strtod(t_before.c_str(), nullptr);
      });
}
