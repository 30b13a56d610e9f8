#include "remnant/driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <thread>

#include "comm_report.hpp"
#include "failure_report.hpp"
#include "remnant/build_info.hpp"
#include "remnant/comm_counters.hpp"
#include "remnant/heap_reuse.hpp"
#include "remnant/parfile.hpp"
#include "remnant/registrar.hpp"
#include "yaml_util.hpp"


extern const char* const remnant_flesh_yaml_text;

namespace remnant {

namespace fs = std::filesystem;

namespace {

// Collects what thorns register, keyed "Thorn::name".
class CollectingRegistrar final : public ThornRegistrar {
 public:
  CollectingRegistrar(std::string thorn, ImplementationTable& impl, ThornCatalog::Hooks& hooks,
                      std::vector<std::string>& errors)
      : thorn_(std::move(thorn)), impl_(impl), hooks_(hooks), errors_(errors) {}
  void function(const std::string& name, ScheduledFunction fn) override {
    if (!impl_.functions.emplace(thorn_ + "::" + name, std::move(fn)).second)
      errors_.push_back("thorn " + thorn_ + " registers function '" + name + "' twice");
  }
  void predicate(const std::string& name, Predicate fn) override {
    if (!impl_.predicates.emplace(thorn_ + "::" + name, std::move(fn)).second)
      errors_.push_back("thorn " + thorn_ + " registers predicate '" + name + "' twice");
  }
  void inverse_dt_limit(std::function<double(Context&)> fn) override { hooks_.inverse_dt.emplace_back(thorn_, std::move(fn)); }
  void termination_check(std::function<std::string(Context&)> fn) override {
    hooks_.termination.emplace_back(thorn_, std::move(fn));
  }
  void progress_fraction(std::function<double(Context&)> fn) override { hooks_.progress.emplace_back(thorn_, std::move(fn)); }
  void grid_factory(std::function<std::unique_ptr<GridDriver>(const GridSetup&)> fn) override {
    hooks_.grid_factories[thorn_] = std::move(fn);
  }
  void recovery(std::function<bool(Context&)> fn) override { hooks_.recovery.emplace_back(thorn_, std::move(fn)); }
  void persistent_state(std::function<std::string(Context&)> save,
                        std::function<void(Context&, const std::string&)> restore) override {
    hooks_.persistent.push_back({thorn_, std::move(save), std::move(restore)});
  }

 private:
  std::string thorn_;
  ImplementationTable& impl_;
  ThornCatalog::Hooks& hooks_;
  std::vector<std::string>& errors_;
};

std::string now_string() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

std::string format_seconds(double s) {
  std::ostringstream os;
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 120) os << std::fixed << std::setprecision(1) << s << " s";
  else if (s < 7200) os << std::fixed << std::setprecision(1) << s / 60 << " min";
  else os << std::fixed << std::setprecision(2) << s / 3600 << " h";
  return os.str();
}

}  // namespace

ThornCatalog::ThornCatalog(std::span<const ThornEntry> thorns) {
  specs_.push_back(parse_thorn_spec(remnant_flesh_yaml_text, "framework/flesh.yaml"));
  std::vector<std::string> errors;
  for (const auto& e : thorns) {
    specs_.push_back(parse_thorn_spec(e.yaml_text, e.yaml_path));
    if (specs_.back().name != e.name)
      throw InputError({e.yaml_path, 1, 1}, "thorn.yaml names thorn '" + specs_.back().name + "' but its folder is " + e.name);
    CollectingRegistrar reg(e.name, impl_, hooks_, errors);
    e.register_fn(reg);
  }
  if (!errors.empty()) throw InputError({}, join(errors, "; "));
  // Declarations and implementations must match one to one.
  for (const auto& spec : specs_) {
    std::set<std::string> declared_fns, declared_preds;
    for (const auto& it : spec.schedule) {
      if (it.is_group) {
        if (!it.repeat_while.empty()) declared_preds.insert(it.repeat_while);
        continue;
      }
      declared_fns.insert(it.name);
      if (!impl_.functions.count(spec.name + "::" + it.name))
        throw InputError(it.where, "function '" + it.name + "' is declared in " + spec.yaml_path +
                                       " but thorn " + spec.name + " registers no C++ implementation "
                                       "(reg.function(\"" + it.name + "\", ...))");
    }
    for (const auto& it : spec.schedule)
      if (it.is_group && !it.repeat_while.empty() && !impl_.predicates.count(spec.name + "::" + it.repeat_while))
        throw InputError(it.where, "group '" + it.name + "' repeats while '" + it.repeat_while + "', but thorn " +
                                       spec.name + " registers no such predicate");
    const std::string prefix = spec.name + "::";
    for (const auto& [key, fn] : impl_.functions)
      if (key.rfind(prefix, 0) == 0 && !declared_fns.count(key.substr(prefix.size())))
        throw InputError({spec.yaml_path, 0, 0}, "thorn " + spec.name + " registers a C++ function '" +
                                                     key.substr(prefix.size()) +
                                                     "' that its thorn.yaml does not declare in 'schedule:'");
    for (const auto& [key, fn] : impl_.predicates)
      if (key.rfind(prefix, 0) == 0 && !declared_preds.count(key.substr(prefix.size())))
        throw InputError({spec.yaml_path, 0, 0}, "thorn " + spec.name + " registers a predicate '" +
                                                     key.substr(prefix.size()) + "' that no group of its thorn.yaml uses");
  }
}

const ThornSpec* ThornCatalog::find(const std::string& name) const {
  for (const auto& s : specs_)
    if (s.name == name) return &s;
  return nullptr;
}

std::vector<std::string> ThornCatalog::names() const {
  std::vector<std::string> out;
  for (std::size_t i = 1; i < specs_.size(); ++i) out.push_back(specs_[i].name);
  return out;
}

std::string ThornCatalog::describe(const std::string& thorn) const {
  std::ostringstream os;
  bool found = false;
  for (const auto& s : specs_) {
    if (!thorn.empty() && s.name != thorn) continue;
    found = true;
    os << s.name << " (" << s.yaml_path << ")";
    if (!s.description.empty()) os << ": " << s.description;
    os << "\n";
    if (!s.provides.empty()) os << "  provides: " << join(s.provides) << "\n";
    if (!s.requirements.empty()) os << "  requires: " << join(s.requirements) << "\n";
    if (s.parameters.empty()) os << "  (no parameters)\n";
    for (const auto& p : s.parameters) {
      os << "  " << s.name << "::" << p.name << "\n";
      os << "      type " << p.type_name() << "; allowed: " << p.allowed() << "; default: "
         << format_param_value(p.default_value) << "; steerable: " << to_string(p.steerable) << "\n";
      os << "      " << p.description << "\n";
    }
    for (const auto& v : s.variables) {
      std::vector<std::string> comps;
      for (const auto& c : v.components) comps.push_back(c.name);
      os << "  variables " << s.name << "::" << v.name << " [" << join(comps) << "] " << to_string(v.centering) << ", "
         << (v.role == VariableRole::evolved ? "evolved" : v.role == VariableRole::derived ? "derived" : "auxiliary")
         << (v.description.empty() ? "" : ": " + v.description) << "\n";
    }
    os << "\n";
  }
  if (!found) {
    std::vector<std::string> all;
    for (const auto& s : specs_) all.push_back(s.name);
    auto near = nearest_names(thorn, all, 3);
    throw InputError({"command line", 0, 0}, "unknown thorn '" + thorn + "'" +
                                                 (near.empty() ? "" : " (did you mean " + join(near) + "?)") +
                                                 "; thorns: " + join(all));
  }
  return os.str();
}

Simulation::Simulation(const ThornCatalog& catalog, const SimulationOptions& opts, MPI_Comm comm)
    : catalog_(catalog), opts_(opts), comm_(comm) {
  Parfile pf = Parfile::load(opts.parfile_path, opts.parfile_text);
  for (std::size_t i = 0; i < opts.overrides.size(); ++i) pf.apply_override(opts.overrides[i], static_cast<int>(i) + 1);
  if (opts.debug) pf.apply_override("Flesh::debug=true", 0);
  parfile_files_ = pf.files;

  const auto compiled = catalog.names();
  if (pf.active_thorns.empty())
    throw InputError({opts.parfile_path, 0, 0}, "the parfile has no 'active_thorns:' list; thorns in this executable: " +
                                                    join(compiled));
  for (const auto& t : pf.active_thorns) {
    if (t == "Flesh") continue;
    if (std::find(compiled.begin(), compiled.end(), t) == compiled.end()) {
      auto near = nearest_names(t, compiled, 3);
      throw InputError(pf.active_where[t], "active thorn '" + t + "' is not compiled into this executable" +
                                               (near.empty() ? "" : " (did you mean " + join(near) + "?)") +
                                               "; thorns: " + join(compiled));
    }
    active_.push_back(t);
  }
  // Capabilities among the active thorns.
  std::map<std::string, std::string> provider;
  for (const auto& t : active_)
    for (const auto& c : catalog.find(t)->provides) {
      if (provider.count(c))
        throw InputError(pf.active_where[t], "capability '" + c + "' is provided by two active thorns: " + provider[c] +
                                                 " and " + t);
      provider[c] = t;
    }
  for (const auto& t : active_)
    for (const auto& c : catalog.find(t)->requirements)
      if (!provider.count(c)) {
        std::vector<std::string> candidates;
        for (const auto& s : catalog.specs())
          if (std::find(s.provides.begin(), s.provides.end(), c) != s.provides.end()) candidates.push_back(s.name);
        throw InputError(pf.active_thorns_where, "active thorn " + t + " requires '" + c + "', which no active thorn provides" +
                                                     (candidates.empty() ? "" : "; activate " + join(candidates, " or ")));
      }

  std::vector<std::string> with_flesh{"Flesh"};
  with_flesh.insert(with_flesh.end(), active_.begin(), active_.end());
  std::vector<const ThornSpec*> specs;
  for (const auto& t : with_flesh) {
    const ThornSpec* s = catalog.find(t);
    specs.push_back(s);
    for (const auto& p : s->parameters) params_.declare(p);
  }
  std::vector<std::string> all_names{"Flesh"};
  for (const auto& n : compiled) all_names.push_back(n);
  apply_parfile(pf, all_names, with_flesh, params_);
  // Groups with an `if:` get storage only when it holds; their parameter is fixed for the run.
  for (const ThornSpec* s : specs) register_variable_groups(*s, params_, vars_);
  vars_.resolve_rhs();
  scheduler_ = std::make_unique<Scheduler>(specs, vars_, params_, catalog.implementations());
  scheduler_->set_debug(params_.get<bool>("Flesh", "debug"));
  ctx_ = std::make_unique<Context>(params_, vars_, comm_);
  ctx_->set_out_dir(params_.get<std::string>("Flesh", "out_dir"));
  ctx_->set_inverse_dt_fn([this] { return inverse_dt_limit(); });
  ctx_->set_active_thorns(active_);
  ctx_->set_bin_hooks(
      [this](const std::string& bin) {
        const std::string thorn = ctx_->current_thorn(), fn = ctx_->current_function();
        scheduler_->run_bin(bin, *ctx_);
        ctx_->set_current(thorn, fn);
      },
      [this] { scheduler_->invalidate_ghosts(); });
  for (const auto& p : catalog.hooks().persistent)
    if (std::find(active_.begin(), active_.end(), p.thorn) != active_.end()) ctx_->add_persistent_state(p);
}

Simulation::~Simulation() = default;

std::string Simulation::resolved_parfile() const {
  std::ostringstream os;
  os << "# Resolved parameters (every default filled in), written by Remnant\n";
  os << "# git revision: " << git_revision() << ", build type: " << build_type() << "\n";
  os << "# from: " << join(parfile_files_) << "\n";
  os << "active_thorns: [" << join(active_) << "]\n";
  std::vector<std::string> with_flesh{"Flesh"};
  with_flesh.insert(with_flesh.end(), active_.begin(), active_.end());
  os << params_.to_yaml(with_flesh);
  return os.str();
}

void Simulation::setup_output_and_grid() {
  const std::string resolved = resolved_parfile();
  ctx_->set_resolved_parfile(resolved);
  // Every rank must hold the same parameters: compare a hash of the resolved parfile.
  unsigned long long h = std::hash<std::string>{}(resolved), hmin = 0, hmax = 0;
  MPI_Allreduce(&h, &hmin, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, comm_);
  MPI_Allreduce(&h, &hmax, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, comm_);
  if (hmin != hmax) throw RunError("the MPI ranks hold different parameters (different parfiles on different nodes?)");
  // Rank 0 writes; every rank learns the outcome, so that a failure stops all of them together.
  ctx_->set_current("Flesh", "create_output_directory");
  std::string failure;
  if (ctx_->rank() == 0) {
    std::error_code ec;
    fs::create_directories(ctx_->out_dir(), ec);
    const std::string path = ctx_->out_dir() + "/parfile.resolved.yaml";
    if (ec) {
      failure = "cannot create output directory '" + ctx_->out_dir() + "' (Flesh::out_dir): " + ec.message();
    } else {
      std::ofstream out(path);
      out << "# date: " << now_string() << "\n" << resolved;
      if (!out) failure = "cannot write " + path + " (Flesh::out_dir)";
    }
  }
  int len = static_cast<int>(failure.size());
  MPI_Bcast(&len, 1, MPI_INT, 0, comm_);
  failure.resize(static_cast<std::size_t>(len));
  MPI_Bcast(failure.data(), len, MPI_CHAR, 0, comm_);
  if (!failure.empty()) throw RunError(failure);
  for (const auto& t : active_) {
    const auto& f = catalog_.hooks().grid_factories;
    if (auto it = f.find(t); it != f.end()) {
      ctx_->set_current(t, "create_grid");
      grid_ = it->second(GridSetup{params_, vars_, comm_});
      ctx_->set_grid(grid_.get());
    }
  }
}

double Simulation::inverse_dt_limit() {
  double local = 0;
  for (const auto& [thorn, fn] : catalog_.hooks().inverse_dt)
    if (std::find(active_.begin(), active_.end(), thorn) != active_.end()) local = std::max(local, fn(*ctx_));
  double global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, comm_);
  comm::count("dt_allreduce", comm::Pattern::allreduce, -1, 1, sizeof(double));
  return global;
}

std::string Simulation::termination_reason() {
  // Rank 0 decides (wall-clock limits differ between ranks) and tells the others.
  std::string reason;
  if (ctx_->rank() == 0)
    for (const auto& [thorn, fn] : catalog_.hooks().termination)
      if (std::find(active_.begin(), active_.end(), thorn) != active_.end()) {
        reason = fn(*ctx_);
        if (!reason.empty()) break;
      }
  int len = static_cast<int>(reason.size());
  MPI_Bcast(&len, 1, MPI_INT, 0, comm_);
  reason.resize(static_cast<std::size_t>(len));
  MPI_Bcast(reason.data(), len, MPI_CHAR, 0, comm_);
  return reason;
}

double Simulation::progress_fraction() {
  double fraction = 0;
  for (const auto& [thorn, fn] : catalog_.hooks().progress)
    if (std::find(active_.begin(), active_.end(), thorn) != active_.end()) fraction = std::max(fraction, fn(*ctx_));
  return fraction;
}

void Simulation::progress_line(double wall_start, double fraction_start, std::int64_t it_start, double t_last,
                               std::int64_t it_last) {
  if (ctx_->rank() != 0 || opts_.quiet) return;
  const double now = MPI_Wtime();
  const auto& c = ctx_->clock();
  const double cells = grid_ ? static_cast<double>(grid_->global_cells()) : 0.0;
  const double rate = now > t_last ? cells * static_cast<double>(c.iteration - it_last) / (now - t_last) : 0.0;
  const double fraction = progress_fraction();
  const double elapsed = now - wall_start;
  // From the progress made by this process (a recovered run starts part-way).
  const double done = fraction - fraction_start;
  const double eta = done > 0 && c.iteration > it_start ? elapsed * (1 - fraction) / done : -1;
  std::printf("it %8lld  t %.6e  dt %.3e  %.3e zone-updates/s  wall %s  ETA %s\n", static_cast<long long>(c.iteration),
              c.time, c.dt, rate, format_seconds(elapsed).c_str(), format_seconds(eta).c_str());
  std::fflush(stdout);
}

void Simulation::run() {
  auto& s = *scheduler_;
  auto& ctx = *ctx_;
  ctx.set_current("Flesh", "run");  // an error outside any scheduled function names the driver
  s.run_bin("startup", ctx);
  s.run_bin("paramcheck", ctx);
  bool recovered = false;
  for (const auto& [thorn, fn] : catalog_.hooks().recovery)
    if (!recovered && std::find(active_.begin(), active_.end(), thorn) != active_.end()) {
      ctx.set_current(thorn, "recovery");
      recovered = fn(ctx);
    }
  ctx.set_recovered(recovered);
  if (recovered) {
    // Checkpoints hold interiors only: every ghost zone is stale now.
    s.invalidate_ghosts();
    s.run_bin("post_recover", ctx);
  } else {
    // A NaN written by initial data is fatal, with the function named.
    s.set_nan_check(true);
    for (const char* bin : {"initial", "postinitial"}) s.run_bin(bin, ctx);
    s.set_nan_check(false);
    s.run_bin("analysis", ctx);
  }
  if (!s.bin_empty("evol")) evolve();
  s.run_bin("terminate", ctx);
  ctx.set_current("Flesh", "driver");
  if (params_.get<bool>("Flesh", "comm_stats")) write_comm_report(s, ctx);
  if (ctx.rank() == 0 && !opts_.quiet && params_.get<bool>("Flesh", "timers")) std::cout << s.timer_table() << std::flush;
}

void Simulation::evolve() {
  auto& s = *scheduler_;
  auto& ctx = *ctx_;
  bool has_termination = false;
  for (const auto& [thorn, fn] : catalog_.hooks().termination)
    has_termination |= std::find(active_.begin(), active_.end(), thorn) != active_.end();
  ctx.set_current("Flesh", "evolve");
  if (!has_termination)
    throw RunError("functions are scheduled in 'evol' but no active thorn decides when the run ends (activate MoL)");
  const auto& every = params_.get<std::int64_t>("Flesh", "progress_every");
  const double wall_start = MPI_Wtime();
  const std::int64_t it_start = ctx.iteration();
  const double fraction_start = progress_fraction();
  double t_last = wall_start;
  std::int64_t it_last = it_start;
  comm::reset();  // comm.tsv counts the evolution, not the initial data
  for (;;) {
    ctx.set_current("Flesh", "termination");
    const std::string reason = termination_reason();
    if (!reason.empty()) {
      ctx.set_termination_reason(reason);
      if (ctx.rank() == 0 && !opts_.quiet)
        std::cout << "Run ends at iteration " << ctx.iteration() << ", t = " << ctx.time() << ": " << reason << std::endl;
      break;
    }
    s.run_bin("prestep", ctx);
    s.run_bin("evol", ctx);
    ++ctx.clock().iteration;
    s.run_bin("poststep", ctx);
    s.run_bin("analysis", ctx);
    s.run_bin("checkpoint", ctx);
    if (every > 0 && ctx.iteration() % every == 0) {
      progress_line(wall_start, fraction_start, it_start, t_last, it_last);
      t_last = MPI_Wtime();
      it_last = ctx.iteration();
    }
  }
}

namespace {

void print_usage(const ExecutableInfo& exe) {
  std::cout << "Usage: " << exe.name << " [options] [parfile.yaml] [Thorn::param=value ...]\n"
            << "Runs the simulation the parfile describes" << (exe.default_parfile.path[0] ? std::string(" (default: the embedded ") + exe.default_parfile.path + ")" : std::string())
            << ".\n\nOptions:\n"
               "  --describe [Thorn]   print every parameter (type, range, default) and variable, then exit\n"
               "  --print-schedule     print the resolved schedule of the parfile, then exit\n"
               "  --print-grid         print the grid layout (levels, blocks, cells, ranks), then exit\n"
               "  --print-parfile      print the resolved parfile (defaults filled in), then exit\n"
               "  --debug              NaN-poison declared outputs and check undeclared writes (Flesh::debug)\n"
               "  --list-thorns        print the thorns compiled into this executable\n"
               "  --version            print the git revision and build type\n"
               "  -h, --help           this help\n"
               "\nOverrides (after the parfile, applied in order):\n"
               "  Thorn::param=value   set one parameter (YAML value: 0.5, [16,16,1], true, keyword)\n"
               "  active_thorns=[A,B]  replace the parfile's thorn list\n"
               "  active_thorns+=[C]   add thorns to it\n";
}

// Agree on failure across ranks during set-up so that no rank waits in a collective forever.
// Returns the lowest failing rank, or -1 when every rank succeeded.
int lowest_failing_rank(bool failed, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  int local = failed ? rank : size, global = size;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MIN, comm);
  return global < size ? global : -1;
}

}  // namespace

int run_main(int argc, char** argv, const ExecutableInfo& exe) {
  MPI_Init(&argc, &argv);
  keep_freed_memory_for_reuse();  // process-wide heap setting (remnant/heap_reuse.hpp)
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // Failure reports travel on their own communicator, apart from the thorns' messages.
  MPI_Comm error_comm = MPI_COMM_NULL;
  MPI_Comm_dup(MPI_COMM_WORLD, &error_comm);
  std::vector<std::string> args(argv + 1, argv + argc);
  enum class Mode { run, describe, schedule, grid, parfile } mode = Mode::run;
  std::string describe_thorn;
  SimulationOptions opts;
  std::string error;
  bool positional_parfile = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-h" || a == "--help") {
      if (rank == 0) print_usage(exe);
      MPI_Finalize();
      return 0;
    } else if (a == "--version") {
      if (rank == 0) std::cout << exe.name << " git " << git_revision() << " (" << build_type() << ")\n";
      MPI_Finalize();
      return 0;
    } else if (a == "--describe") {
      mode = Mode::describe;
      if (i + 1 < args.size() && args[i + 1].rfind("-", 0) != 0 && args[i + 1].find("::") == std::string::npos &&
          args[i + 1].find('.') == std::string::npos)
        describe_thorn = args[++i];
    } else if (a == "--print-schedule") {
      mode = Mode::schedule;
    } else if (a == "--print-grid") {
      mode = Mode::grid;
    } else if (a == "--print-parfile") {
      mode = Mode::parfile;
    } else if (a == "--debug") {
      opts.debug = true;
    } else if (a == "--list-thorns") {
      if (rank == 0)
        for (const auto& t : exe.thorns) std::cout << t.name << "  (" << t.yaml_path << ")\n";
      MPI_Finalize();
      return 0;
    } else if (a.rfind("--", 0) == 0) {
      error = "command line: error: unknown option '" + a + "' (see --help)";
    } else if ((a.find("::") != std::string::npos && a.find('=') != std::string::npos) || is_active_thorns_override(a)) {
      opts.overrides.push_back(a);
    } else if (!positional_parfile) {
      opts.parfile_path = a;
      positional_parfile = true;
    } else {
      error = "command line: error: a second parfile '" + a + "' (only one is allowed; use include: to layer)";
    }
  }
  std::string default_text;
  if (!positional_parfile && error.empty() && mode != Mode::describe) {
    if (!exe.default_parfile.path[0]) {
      error = "command line: error: no parfile given and " + std::string(exe.name) + " embeds no default (see --help)";
    } else {
      opts.parfile_path = std::string("<embedded ") + exe.default_parfile.path + ">";
      default_text = exe.default_parfile.text;
      opts.parfile_text = &default_text;
      if (rank == 0 && mode == Mode::run)
        std::cout << "No parfile given: running the embedded default " << exe.default_parfile.path << "\n";
    }
  }
  if (!positional_parfile && error.empty() && mode == Mode::run && rank == 0) std::cout << std::flush;

  std::unique_ptr<ThornCatalog> catalog;
  std::unique_ptr<Simulation> sim;
  int exit_code = 0;
  try {
    if (!error.empty()) throw InputError({}, error);
    catalog = std::make_unique<ThornCatalog>(exe.thorns);
    if (mode == Mode::describe) {
      if (rank == 0) std::cout << catalog->describe(describe_thorn);
    } else {
      sim = std::make_unique<Simulation>(*catalog, opts, MPI_COMM_WORLD);
    }
    error.clear();
  } catch (const std::exception& e) {
    error = e.what();
    // InputError already reads "file:line:col: error: ..."; prefix plain set-up failures.
    if (!dynamic_cast<const InputError*>(&e)) error = "error: " + error;
  }
  if (const int lowest = lowest_failing_rank(!error.empty(), MPI_COMM_WORLD); lowest >= 0) {
    // Set-up is the same on every rank: the lowest failing rank speaks for all, once.
    if (rank == lowest) std::cerr << (rank > 0 ? "[rank " + std::to_string(rank) + "] " : std::string()) << error << std::endl;
    MPI_Finalize();
    return 1;
  }
  if (mode == Mode::describe) {
    MPI_Finalize();
    return 0;
  }
  if (mode == Mode::schedule || mode == Mode::parfile) {
    if (rank == 0) std::cout << (mode == Mode::schedule ? sim->scheduler().print() : sim->resolved_parfile());
    MPI_Finalize();
    return 0;
  }
  try {
    sim->setup_output_and_grid();
    if (mode == Mode::grid) {
      std::string d = sim->grid() ? sim->grid()->describe() : std::string("no active thorn provides a grid");
      if (!d.empty() && d.back() != '\n') d += '\n';
      if (rank == 0) std::cout << d;
    } else {
      sim->run();
    }
  } catch (const std::exception& e) {
    const Context& ctx = sim->context();
    int nranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    std::string message = failure_message(e, ctx.current_thorn(), ctx.current_function(), rank, nranks);
    // A thorn may know a likely cause (MoL: a time step above the stability limit).
    if (ctx.has_service("failure_hint"))
      if (const auto& hint = ctx.service<std::string>("failure_hint"); !hint.empty()) message += "\n  likely cause: " + hint;
    const FailureOutcome outcome = report_failure(message, error_comm);
    if (!outcome.all_failed) {
      // Some rank still runs (maybe waiting in a collective): stop them all. The lowest failing
      // rank aborts first; the others give it time, so that the runtime names that rank.
      if (!outcome.printed) std::this_thread::sleep_for(std::chrono::seconds(5));
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    exit_code = 1;
  }
  sim.reset();
  MPI_Comm_free(&error_comm);
  MPI_Finalize();
  return exit_code;
}

}  // namespace remnant
