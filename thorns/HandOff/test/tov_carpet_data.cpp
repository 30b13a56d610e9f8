#include "tov_carpet_data.hpp"

#include <mpi.h>
#include <unistd.h>

#include <span>

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace handoff_test {

TovCarpetData::TovCarpetData(const std::string& folder) {
  // One folder for all ranks (rank 0's pid).
  long pid = static_cast<long>(::getpid());
  MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  dir = std::filesystem::temp_directory_path() / (folder + "_" + std::to_string(pid));
  if (rank == 0) std::filesystem::create_directories(dir);
}

TovCarpetData::~TovCarpetData() {
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank == 0) std::filesystem::remove_all(dir);
}

void TovCarpetData::write(const remnant::handoff::synthetic::SyntheticCarpet& spec,
                          const remnant::handoff::synthetic::Field& value) {
  files = remnant::handoff::synthetic::write_synthetic_carpet(dir.string(), spec, value, rank == 0);
  MPI_Barrier(MPI_COMM_WORLD);
}

std::string TovCarpetData::files_override() const {
  std::string s = "HandOff::files=[";
  for (std::size_t i = 0; i < files.size(); ++i) s += (i ? "," : "") + files[i];
  return s + "]";
}

const remnant::ThornCatalog& compiled_catalog() {
  static const remnant::ThornCatalog catalog(remnant_compiled_thorns());
  return catalog;
}

remnant::SimulationOptions handoff_options(const TovCarpetData& data, const std::vector<std::string>& overrides) {
  remnant::SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/handoff_tov_cyl_2d.yaml";
  o.quiet = true;
  o.overrides = {data.files_override()};
  o.overrides.insert(o.overrides.end(), overrides.begin(), overrides.end());
  return o;
}

}  // namespace handoff_test
