#pragma once
// Runs a whole MHD simulation from parfile text (tests of the magnetic evolution) and gives access
// to its blocks and groups afterwards.
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <unistd.h>

#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace remnant::grmhd::test {

class MhdRun {
 public:
  explicit MhdRun(const std::string& parfile, std::vector<std::string> overrides = {}) {
    static const ThornCatalog catalog(remnant_compiled_thorns());
    static int count = 0;
    dir_ = std::filesystem::temp_directory_path() /
           ("remnant_mhd_" + std::to_string(::getpid()) + "_" + std::to_string(count++));
    std::filesystem::create_directories(dir_);
    const std::string par = (dir_ / "run.yaml").string();
    std::ofstream(par) << parfile;
    SimulationOptions o;
    o.parfile_path = par;
    o.quiet = true;
    o.overrides = std::move(overrides);
    o.overrides.push_back("Flesh::out_dir=" + (dir_ / "out").string());
    sim_ = std::make_unique<Simulation>(catalog, o, MPI_COMM_WORLD);
    sim_->setup_output_and_grid();
    sim_->run();
  }
  ~MhdRun() {
    sim_.reset();
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  Simulation& sim() { return *sim_; }
  int group(const std::string& name) const { return sim_->vars().find(name); }
  std::span<Block* const> blocks() { return sim_->grid()->local_blocks(); }

 private:
  std::filesystem::path dir_;
  std::unique_ptr<Simulation> sim_;
};

// The common part of the test parfiles: an ideal gas, MoL RK3, the magnetic field evolved.
inline std::string mhd_parfile(const std::string& grid, const std::string& grmhd, const std::string& mol,
                               double gamma = 2.0) {
  return "active_thorns: [Grid, MoL, Spacetime, EOS, Atmosphere, Con2Prim, HydroBase, GRMHD]\n"
         "Grid: {" + grid + "}\n"
         "MoL: {method: rk3, " + mol + "}\n"
         "EOS: {type: ideal_gas, gamma: " + std::to_string(gamma) + ", rho_max: 1.0e3, T_max: 1.0e7}\n"
         "Atmosphere: {rho_thr: 1.0e-10}\n"
         "HydroBase: {magnetic_field: evolved}\n"
         "GRMHD: {" + grmhd + "}\n";
}

}  // namespace remnant::grmhd::test
