#pragma once
// Test helper shared by the HandOff fixtures of a TOV star as 3D Carpet data (TovCarpet,
// MetricTov, FlooredTov): the BU0 star (K = 100, Gamma = 2, rho_c = 1.28e-3), a temporary folder
// all ranks share (rank 0's pid; rank 0 writes the files and removes the folder), and the options
// that hand the files to parfiles/handoff_tov_cyl_2d.yaml. A fixture adds its layout and variables
// (write()). And the message of a hand-off's error (message_of).
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "TOV/tov_solver.hpp"
#include "remnant/driver.hpp"
#include "synthetic_carpet.hpp"

namespace handoff_test {

class TovCarpetData {
 public:
  std::unique_ptr<remnant::tov::ColdSlice> slice = remnant::tov::polytrope_slice(100.0, 2.0, 0.5);
  remnant::tov::TovStar star{*slice, 1.28e-3};
  std::filesystem::path dir;
  std::vector<std::string> files;
  int rank = 0;

  // folder: the temporary folder's name (the pid is appended); distinct for data sets that live at
  // once in one process.
  explicit TovCarpetData(const std::string& folder);
  ~TovCarpetData();
  TovCarpetData(const TovCarpetData&) = delete;
  TovCarpetData& operator=(const TovCarpetData&) = delete;

  // Rank 0 writes the data of `spec` with `value`; every rank gets the file names.
  void write(const remnant::handoff::synthetic::SyntheticCarpet& spec, const remnant::handoff::synthetic::Field& value);
  // HandOff::files=[...] naming the data's files.
  std::string files_override() const;
};

// The compiled thorns' catalog, built once per process.
const remnant::ThornCatalog& compiled_catalog();

// A quiet run of parfiles/handoff_tov_cyl_2d.yaml on the data's files, then `overrides` (later
// settings win: an override may name other files).
remnant::SimulationOptions handoff_options(const TovCarpetData& data, const std::vector<std::string>& overrides);

// The message of the exception f() throws ("" when it throws none).
template <class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace handoff_test
