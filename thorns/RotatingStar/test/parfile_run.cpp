#include "parfile_run.hpp"

#include <span>
#include <unistd.h>

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace remnant::rotstar::test {

ParfileRun::ParfileRun(const std::string& parfile, const std::string& tag, const std::vector<std::string>& overrides)
    : out_{std::filesystem::temp_directory_path() / ("remnant_" + tag + "_" + std::to_string(::getpid()))} {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/" + parfile;
  o.quiet = true;
  o.overrides = overrides;
  o.overrides.push_back("Flesh::out_dir=" + out_.path.string());
  sim_ = std::make_unique<Simulation>(catalog, o, MPI_COMM_WORLD);
  sim_->setup_output_and_grid();
  sim_->run();
}

analysis::StarDiagnostics initial_diagnostics(const std::string& parfile, const std::string& tag,
                                              std::vector<std::string> overrides) {
  overrides.insert(overrides.begin(), {"MoL::max_iterations=0", "MoL::final_time=-1", "IO::hdf5_every_time=0"});
  return ParfileRun(parfile, tag, overrides).history().back();
}

RnsParameters drns_parameters() {
  RnsParameters p;
  p.law = RotationLaw::j_constant;
  p.omega = 0.02575;
  p.A2 = 70;
  return p;
}

}  // namespace remnant::rotstar::test
