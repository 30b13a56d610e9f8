// Reads a hand-off's handoff_profiles.tsv (comment lines skipped) for the HandOff tests.
#pragma once

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace handoff_test {

using ProfileRow = std::array<double, 11>;

inline std::vector<ProfileRow> read_handoff_profiles(const std::filesystem::path& file) {
  std::vector<ProfileRow> rows;
  std::ifstream prof(file);
  std::string row;
  while (std::getline(prof, row)) {
    if (row.empty() || row[0] == '#') continue;
    std::istringstream fields(row);
    ProfileRow v{};
    for (double& x : v) fields >> x;
    rows.push_back(v);
  }
  return rows;
}

}  // namespace handoff_test
