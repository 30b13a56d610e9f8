#pragma once
// For a thorn's unit tests: its parsed thorn.yaml and a registrar that records the functions it
// registers, so that scheduled functions can be called directly on a Context.
#include <gtest/gtest.h>
#include <mpi.h>

#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "remnant/context.hpp"
#include "remnant/parameters.hpp"
#include "remnant/registrar.hpp"
#include "remnant/thorn_spec.hpp"
#include "remnant/variables.hpp"

namespace remnant::test {

struct RecordingRegistrar : ThornRegistrar {
  std::map<std::string, ScheduledFunction> fns;
  std::map<std::string, Predicate> predicates;
  void function(const std::string& n, ScheduledFunction f) override { fns[n] = std::move(f); }
  void predicate(const std::string& n, Predicate f) override { predicates[n] = std::move(f); }
  void inverse_dt_limit(std::function<double(Context&)>) override {}
  void termination_check(std::function<std::string(Context&)>) override {}
  void progress_fraction(std::function<double(Context&)>) override {}
  void grid_factory(std::function<std::unique_ptr<GridDriver>(const GridSetup&)>) override {}
};

// thorns/<thorn>/thorn.yaml of the source tree, parsed.
inline ThornSpec thorn_spec_from_source(const std::string& source_dir, const std::string& thorn) {
  const std::string path = source_dir + "/thorns/" + thorn + "/thorn.yaml";
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return parse_thorn_spec(s.str(), path);
}

// The binding of a thorn that provides one capability through one function scheduled in startup:
// its thorn.yaml says so (after `after`, unless empty) and its registration binds the function.
inline void expect_startup_provider(const ThornSpec& t, const std::string& thorn, const std::string& capability,
                                    const std::string& after, void (*register_thorn)(ThornRegistrar&)) {
  const std::string startup = thorn + "_Startup";
  EXPECT_EQ(t.name, thorn);
  ASSERT_EQ(t.provides.size(), 1u);
  EXPECT_EQ(t.provides[0], capability);
  ASSERT_EQ(t.schedule.size(), 1u);
  EXPECT_EQ(t.schedule[0].name, startup);
  EXPECT_EQ(t.schedule[0].in, "startup");
  if (!after.empty()) {
    ASSERT_EQ(t.schedule[0].after.size(), 1u);
    EXPECT_EQ(t.schedule[0].after[0].name, after);
  }
  RecordingRegistrar r;
  register_thorn(r);
  EXPECT_EQ(r.fns.count(startup), 1u);
}

// A Context with a thorn's parameters declared (at their defaults; params.set changes them) and the
// functions its registration binds (r.fns.at(name)(ctx)).
struct ThornContext {
  Parameters params;
  VariableRegistry vars;
  Context ctx{params, vars, MPI_COMM_WORLD};
  RecordingRegistrar r;
  ThornContext(const ThornSpec& t, void (*register_thorn)(ThornRegistrar&)) {
    for (const auto& p : t.parameters) params.declare(p);
    register_thorn(r);
  }
};

}  // namespace remnant::test
