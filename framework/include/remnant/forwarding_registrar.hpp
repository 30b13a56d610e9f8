#pragma once
// A ThornRegistrar that passes every registration on to another: the base of wrappers that change
// one kind of registration of a thorn (tests replacing or extending a scheduled function) and
// forward the rest unchanged.
#include <utility>

#include "remnant/registrar.hpp"

namespace remnant {

class ForwardingRegistrar : public ThornRegistrar {
 public:
  explicit ForwardingRegistrar(ThornRegistrar& target) : target_(target) {}
  void function(const std::string& name, ScheduledFunction fn) override { target_.function(name, std::move(fn)); }
  void predicate(const std::string& name, Predicate fn) override { target_.predicate(name, std::move(fn)); }
  void inverse_dt_limit(std::function<double(Context&)> fn) override { target_.inverse_dt_limit(std::move(fn)); }
  void termination_check(std::function<std::string(Context&)> fn) override { target_.termination_check(std::move(fn)); }
  void progress_fraction(std::function<double(Context&)> fn) override { target_.progress_fraction(std::move(fn)); }
  void recovery(std::function<bool(Context&)> fn) override { target_.recovery(std::move(fn)); }
  void persistent_state(std::function<std::string(Context&)> save,
                        std::function<void(Context&, const std::string&)> restore) override {
    target_.persistent_state(std::move(save), std::move(restore));
  }
  void grid_factory(std::function<std::unique_ptr<GridDriver>(const GridSetup&)> fn) override {
    target_.grid_factory(std::move(fn));
  }

 private:
  ThornRegistrar& target_;
};

}  // namespace remnant
