#pragma once
// How a thorn binds its C++ code to the functions declared in its thorn.yaml.
//
//   REMNANT_REGISTER_THORN(WaveToy) {
//     reg.function("WaveToy_RHS", &compute_rhs);        // void(Context&)
//     reg.inverse_dt_limit(&max_inverse_dt);             // double(Context&)
//   }
//
// The flesh checks at start-up that every scheduled function declared in thorn.yaml has exactly
// one implementation and every implementation is declared.
#include <functional>
#include <memory>
#include <string>

namespace remnant {

class Context;
class GridDriver;
struct GridSetup;

using ScheduledFunction = std::function<void(Context&)>;
using Predicate = std::function<bool(Context&)>;

class ThornRegistrar {
 public:
  virtual ~ThornRegistrar() = default;
  // A function named in thorn.yaml `schedule:` entries.
  virtual void function(const std::string& name, ScheduledFunction fn) = 0;
  // A predicate named by a group's `repeat_while:` (e.g. MoL's substep loop).
  virtual void predicate(const std::string& name, Predicate fn) = 0;
  // Contribution to the time step: returns the largest 1/dt this thorn allows on this rank at
  // Courant factor 1 (for example max over cells of signal speed / dx). MoL combines all of them.
  virtual void inverse_dt_limit(std::function<double(Context&)> fn) = 0;
  // Asked before every iteration; returning a non-empty reason ends the run.
  virtual void termination_check(std::function<std::string(Context&)> fn) = 0;
  // Fraction of the run done, in [0, 1], for the ETA of the progress line (MoL knows final_time).
  virtual void progress_fraction(std::function<double(Context&)> fn) = 0;
  // Recovery: the thorn that reads checkpoints (IO) returns true when it restored a run; the
  // driver then skips `initial`/`postinitial` and runs `post_recover` instead.
  virtual void recovery(std::function<bool(Context&)> fn) { (void)fn; }
  // Thorn state beyond grid variables that a bit-identical continuation needs, saved as text in
  // checkpoints (e.g. a counter of steps since the last metric solve).
  virtual void persistent_state(std::function<std::string(Context&)> save,
                                std::function<void(Context&, const std::string&)> restore) {
    (void)save;
    (void)restore;
  }
  // The thorn that provides capability `grid` creates the mesh.
  virtual void grid_factory(std::function<std::unique_ptr<GridDriver>(const GridSetup&)> fn) = 0;
};

}  // namespace remnant

#define REMNANT_REGISTER_THORN(Name) \
  void remnant_register_thorn_##Name(::remnant::ThornRegistrar& reg)
