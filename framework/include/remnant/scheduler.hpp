#pragma once
// The schedule: bins, groups, ordering (before/after and writer-before-reader), conditions,
// repeated groups, automatic ghost synchronisation, debug checks of declarations, timers.
#include <chrono>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <vector>

#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "remnant/thorn_spec.hpp"

namespace remnant {

struct ScheduleNode {
  const ScheduleItem* item = nullptr;
  std::vector<ScheduleNode> children;        // groups only, in run order
  ScheduledFunction fn;                      // functions only
  Predicate repeat;                          // groups with repeat_while
  std::vector<int> reads_everywhere;         // group ids whose ghosts must be valid first
  std::vector<int> reads, writes_interior, writes_everywhere;
  std::vector<int> declared;                 // sorted union of reads and writes (--debug access checks)
  const std::int64_t* every_value = nullptr;   // `every: Thorn::param`
  const ParamValue* condition_value = nullptr;
  ParamValue condition_expected;             // for equal / not_equal
  // Timer
  double seconds = 0;
  long calls = 0;
  double work_seconds = 0;  // CPU time outside MPI (comm.tsv; see remnant/comm_counters.hpp)
};

struct ImplementationTable {
  std::map<std::string, ScheduledFunction> functions;   // "Thorn::name"
  std::map<std::string, Predicate> predicates;          // "Thorn::name"
};

class Scheduler {
 public:
  // Builds the schedule from the active thorns' specs (in activation order). Throws InputError for
  // unknown bins/groups/targets and for cycles (the message prints the cycle).
  Scheduler(const std::vector<const ThornSpec*>& thorns, const VariableRegistry& vars,
            const Parameters& params, const ImplementationTable& impl);

  // Runs one bin. The flesh passes the iteration for `every:` conditions.
  void run_bin(const std::string& bin, Context& ctx);
  bool bin_empty(const std::string& bin) const;

  std::string print() const;         // --print-schedule
  std::string timer_table() const;   // seconds per scheduled function
  double sync_seconds() const { return sync_seconds_; }  // automatic ghost synchronisation
  long sync_calls() const { return sync_calls_; }
  void set_debug(bool on) { debug_ = on; }
  // While on (initial data), a NaN in the interior of a declared output is fatal, debug or not.
  void set_nan_check(bool on) { nan_check_ = on; }
  // Ghost state: invalidate everything (after recovery, regrid).
  void invalidate_ghosts();
  std::vector<const ScheduleNode*> all_functions() const;

 private:
  void run_node(ScheduleNode& node, Context& ctx);
  void call_function(ScheduleNode& node, Context& ctx);
  bool condition_holds(const ScheduleNode& node, const Context& ctx) const;
  std::vector<ScheduleNode> build_container(const std::string& container, const std::vector<const ScheduleItem*>& items,
                                            const ImplementationTable& impl, const VariableRegistry& vars,
                                            const Parameters& params, int depth);
  std::map<std::string, std::vector<ScheduleNode>> bins_;
  std::vector<bool> ghosts_valid_;
  std::map<std::string, std::vector<const ScheduleItem*>> by_container_;
  std::set<std::string> off_groups_;  // groups with a fixed false `if:` (or inside one)
  const VariableRegistry* vars_;
  bool debug_ = false;
  bool nan_check_ = false;
  double sync_seconds_ = 0;
  long sync_calls_ = 0;
};

}  // namespace remnant
