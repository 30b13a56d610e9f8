#pragma once
// For a thorn's unit tests: its parsed thorn.yaml and a registrar that records the functions it
// registers, so that scheduled functions can be called directly on a Context.
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include "remnant/registrar.hpp"
#include "remnant/thorn_spec.hpp"

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

}  // namespace remnant::test
