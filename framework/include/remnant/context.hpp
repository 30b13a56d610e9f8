#pragma once
// What a scheduled function sees: parameters, the grid, the simulation clock, shared services.
#include <any>
#include <functional>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "remnant/error.hpp"
#include "remnant/grid.hpp"
#include "remnant/parameters.hpp"
#include "remnant/variables.hpp"

namespace remnant {

struct SimulationClock {
  std::int64_t iteration = 0;
  double time = 0.0;
  double dt = 0.0;
  int substep = 0;          // MoL substep counter within an iteration (0-based)
};

class Context {
 public:
  Context(const Parameters& params, const VariableRegistry& vars, MPI_Comm comm);

  const Parameters& params() const { return *params_; }
  template <class T>
  const T& param(std::string_view thorn, std::string_view name) const {
    return params_->get<T>(thorn, name);
  }
  const VariableRegistry& vars() const { return *vars_; }
  // Group id for "Thorn::group"; throws RunError when absent.
  int var(const std::string& full_name) const;
  // In --debug runs the scheduler sets the groups (sorted ids) that the running function declares in
  // reads:/writes:; a view of any other group is then an error naming the function and the group.
  // nullptr: no check. Returns the previous setting (nested bins restore it).
  const std::vector<int>* set_declared_groups(const std::vector<int>* groups) {
    const std::vector<int>* previous = declared_groups_;
    declared_groups_ = groups;
    return previous;
  }
  void check_access(int group) const {
    if (declared_groups_) check_declared(group);
  }

  GridDriver& grid() const;
  bool has_grid() const { return grid_ != nullptr; }
  void set_grid(GridDriver* g) { grid_ = g; }

  SimulationClock& clock() { return clock_; }
  const SimulationClock& clock() const { return clock_; }
  double time() const { return clock_.time; }
  double dt() const { return clock_.dt; }
  std::int64_t iteration() const { return clock_.iteration; }

  MPI_Comm comm() const { return comm_; }
  int rank() const { return rank_; }
  int nranks() const { return nranks_; }
  const std::string& out_dir() const { return out_dir_; }
  void set_out_dir(std::string d) { out_dir_ = std::move(d); }

  // Shared C++ objects between thorns (an EOS, a con2prim function), published by name.
  template <class T>
  void publish(const std::string& name, std::shared_ptr<T> obj) { services_[name] = std::move(obj); }
  template <class T>
  T& service(const std::string& name) const {
    auto it = services_.find(name);
    if (it == services_.end()) throw RunError("no service named '" + name + "' was published");
    auto p = std::any_cast<std::shared_ptr<T>>(&it->second);
    if (!p) throw RunError("service '" + name + "' has another type than " + typeid(T).name());
    return **p;
  }
  bool has_service(const std::string& name) const { return services_.count(name) != 0; }

  // The scheduled function now running (for log messages).
  const std::string& current_thorn() const { return current_thorn_; }
  const std::string& current_function() const { return current_function_; }
  void set_current(std::string thorn, std::string function) {
    current_thorn_ = std::move(thorn);
    current_function_ = std::move(function);
  }

  // Largest 1/dt allowed by the thorns' CFL limits at Courant factor 1, over all ranks.
  double max_inverse_dt() const { return inverse_dt_fn_ ? inverse_dt_fn_() : 0.0; }
  void set_inverse_dt_fn(std::function<double()> f) { inverse_dt_fn_ = std::move(f); }

  // Why the run ends (set by the driver before the `terminate` bin), e.g. "reached MoL::final_time".
  const std::string& termination_reason() const { return termination_reason_; }
  void set_termination_reason(std::string r) { termination_reason_ = std::move(r); }
  bool recovered() const { return recovered_; }
  // The iteration the run was recovered at (set with set_recovered, after the clock was restored).
  std::int64_t recovered_iteration() const { return recovered_iteration_; }
  void set_recovered(bool r) {
    recovered_ = r;
    recovered_iteration_ = r ? clock_.iteration : 0;
  }

  // Persistent thorn state for checkpoints: thorn name -> save/restore.
  struct PersistentState {
    std::string thorn;
    std::function<std::string(Context&)> save;
    std::function<void(Context&, const std::string&)> restore;
  };
  const std::vector<PersistentState>& persistent_states() const { return persistent_states_; }
  void add_persistent_state(PersistentState s) { persistent_states_.push_back(std::move(s)); }
  // Names of the active thorns, in activation order (provenance).
  const std::vector<std::string>& active_thorns() const { return active_thorns_; }
  void set_active_thorns(std::vector<std::string> t) { active_thorns_ = std::move(t); }
  // The resolved parfile text (provenance for outputs and checkpoints).
  const std::string& resolved_parfile() const { return resolved_parfile_; }
  void set_resolved_parfile(std::string t) { resolved_parfile_ = std::move(t); }

  // For the grid thorn after a regrid: run a bin now (e.g. "post_regrid") and mark every ghost
  // zone stale (the next reader synchronises).
  void run_bin(const std::string& bin) {
    if (run_bin_fn_) run_bin_fn_(bin);
  }
  void invalidate_ghosts() {
    if (invalidate_fn_) invalidate_fn_();
  }
  void set_bin_hooks(std::function<void(const std::string&)> run, std::function<void()> invalidate) {
    run_bin_fn_ = std::move(run);
    invalidate_fn_ = std::move(invalidate);
  }

  void info(const std::string& msg) const;   // rank 0 only
  void warn(const std::string& msg) const;   // any rank, prefixed with rank, thorn and function

 private:
  void check_declared(int group) const;

  const Parameters* params_;
  const VariableRegistry* vars_;
  GridDriver* grid_ = nullptr;
  SimulationClock clock_;
  MPI_Comm comm_;
  int rank_ = 0, nranks_ = 1;
  std::string out_dir_ = ".";
  std::map<std::string, std::any> services_;
  std::string current_thorn_, current_function_;
  std::function<double()> inverse_dt_fn_;
  std::string termination_reason_;
  bool recovered_ = false;
  std::int64_t recovered_iteration_ = 0;
  std::vector<PersistentState> persistent_states_;
  std::vector<std::string> active_thorns_;
  std::string resolved_parfile_;
  std::function<void(const std::string&)> run_bin_fn_;
  std::function<void()> invalidate_fn_;
  const std::vector<int>* declared_groups_ = nullptr;
};

}  // namespace remnant
