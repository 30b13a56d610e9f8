#pragma once
// Runs a parfile given as text in a fresh temporary folder and returns the Analysis history rows
// (the whole-run tests of the rest-mass budget and the outflow boundary).
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace remnant::grmhd::test {

inline std::vector<analysis::StarDiagnostics> run_parfile_history(const std::string& name,
                                                                  const std::string& parfile_text) {
  static const ThornCatalog catalog(remnant_compiled_thorns());
  const auto dir = std::filesystem::temp_directory_path() / ("remnant_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string par = (dir / (name + ".yaml")).string();
  std::ofstream(par) << parfile_text;
  SimulationOptions o;
  o.parfile_path = par;
  o.quiet = true;
  o.overrides = {"Flesh::out_dir=" + (dir / "out").string()};
  Simulation sim(catalog, o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  auto rows = sim.context().service<analysis::History>("Analysis::history").rows;
  std::filesystem::remove_all(dir);
  return rows;
}

}  // namespace remnant::grmhd::test
