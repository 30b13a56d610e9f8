#pragma once
// The driver: builds a simulation from the compiled thorns and a parfile, runs the bins, reports.
#include <mpi.h>

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "remnant/context.hpp"
#include "remnant/parameters.hpp"
#include "remnant/scheduler.hpp"
#include "remnant/thorn_spec.hpp"
#include "remnant/thorn_table.hpp"
#include "remnant/variables.hpp"

namespace remnant {

// Entry point of every executable (generated main.cpp): MPI, command line, errors, exit code.
int run_main(int argc, char** argv, const ExecutableInfo& exe);

struct SimulationOptions {
  std::string parfile_path;              // shown in messages; read from disk unless parfile_text is set
  const std::string* parfile_text = nullptr;
  std::vector<std::string> overrides;    // "Thorn::param=value"
  bool debug = false;                    // same as Flesh::debug=true
  bool quiet = false;                    // no progress lines or timer table (tests)
};

// Compiled thorns: their parsed thorn.yaml and C++ implementations, checked against each other.
class ThornCatalog {
 public:
  explicit ThornCatalog(std::span<const ThornEntry> thorns);
  const std::vector<ThornSpec>& specs() const { return specs_; }
  const ThornSpec* find(const std::string& name) const;
  std::vector<std::string> names() const;  // without the Flesh
  std::string describe(const std::string& thorn) const;  // "" = all thorns
  const ImplementationTable& implementations() const { return impl_; }

  struct Hooks {
    std::vector<std::pair<std::string, std::function<double(Context&)>>> inverse_dt, progress;
    std::vector<std::pair<std::string, std::function<std::string(Context&)>>> termination;
    std::map<std::string, std::function<std::unique_ptr<GridDriver>(const GridSetup&)>> grid_factories;
    std::vector<std::pair<std::string, std::function<bool(Context&)>>> recovery;
    std::vector<Context::PersistentState> persistent;
  };
  const Hooks& hooks() const { return hooks_; }

 private:
  std::vector<ThornSpec> specs_;  // Flesh first
  ImplementationTable impl_;
  Hooks hooks_;
};

class Simulation {
 public:
  Simulation(const ThornCatalog& catalog, const SimulationOptions& opts, MPI_Comm comm);
  ~Simulation();

  // Creates the output directory, writes the resolved parfile, creates the grid.
  void setup_output_and_grid();
  // Runs startup to terminate.
  void run();

  Context& context() { return *ctx_; }
  const Parameters& params() const { return params_; }
  const VariableRegistry& vars() const { return vars_; }
  Scheduler& scheduler() { return *scheduler_; }
  GridDriver* grid() { return grid_.get(); }
  const std::vector<std::string>& active_thorns() const { return active_; }
  std::string resolved_parfile() const;
  // Largest allowed 1/dt over thorns and ranks (MoL uses this).
  double inverse_dt_limit();

 private:
  void evolve();
  std::string termination_reason();
  double progress_fraction();
  void progress_line(double wall_start, double fraction_start, std::int64_t it_start, double t_last, std::int64_t it_last);

  const ThornCatalog& catalog_;
  SimulationOptions opts_;
  MPI_Comm comm_;
  std::vector<std::string> active_;
  Parameters params_;
  VariableRegistry vars_;
  std::unique_ptr<Scheduler> scheduler_;
  std::unique_ptr<Context> ctx_;
  std::unique_ptr<GridDriver> grid_;
  std::vector<std::string> parfile_files_;
};

}  // namespace remnant
