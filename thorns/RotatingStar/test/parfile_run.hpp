#pragma once
// The run set-up of the RotatingStar tests that start whole simulations: parfiles/<parfile> with
// command-line overrides, quiet, writing into a temporary out_dir that is removed with the run
// (also when the set-up throws), set up and run to MoL::max_iterations.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "RotatingStar/rns_solver.hpp"
#include "remnant/driver.hpp"

namespace remnant::rotstar::test {

class ParfileRun {
 public:
  // `tag` names the temporary out_dir (<tmp>/remnant_<tag>_<pid>).
  ParfileRun(const std::string& parfile, const std::string& tag, const std::vector<std::string>& overrides);
  Context& context() { return sim_->context(); }
  const std::filesystem::path& out_dir() const { return out_.path; }
  // Analysis's rows, one per analysed step.
  const std::vector<analysis::StarDiagnostics>& history() {
    return context().service<analysis::History>("Analysis::history").rows;
  }

 private:
  struct TempDir {
    std::filesystem::path path;
    ~TempDir() { std::filesystem::remove_all(path); }
  };
  TempDir out_;                      // destroyed after the simulation that writes into it
  std::unique_ptr<Simulation> sim_;
};

// The parfile's set-up without a step (MoL::max_iterations=0): Analysis's row at t = 0.
analysis::StarDiagnostics initial_diagnostics(const std::string& parfile, const std::string& tag,
                                              std::vector<std::string> overrides = {});

// The rotation law of parfiles/drns_sph_2d.yaml and magnetized_drns.yaml (j-constant, Omega_c =
// 0.02575, A^2 = 70; on the K = 100, Gamma = 2 polytrope), without a field.
RnsParameters drns_parameters();

}  // namespace remnant::rotstar::test
