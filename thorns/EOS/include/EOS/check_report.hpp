#pragma once
// What the load-time checks found: counted warnings and facts, each naming file and dataset.
#include <cstdint>
#include <string>
#include <vector>

namespace remnant::eos {

struct CheckIssue {
  enum class Level { info, warning };
  Level level = Level::warning;
  std::string file, dataset;
  std::uint64_t count = 0;   // how many grid points are affected
  std::string message;       // what and, where useful, the first location
  std::string str() const;
};

struct CheckReport {
  std::vector<CheckIssue> issues;
  void warn(std::string file, std::string dataset, std::uint64_t count, std::string msg) {
    issues.push_back({CheckIssue::Level::warning, std::move(file), std::move(dataset), count, std::move(msg)});
  }
  void info(std::string file, std::string dataset, std::uint64_t count, std::string msg) {
    issues.push_back({CheckIssue::Level::info, std::move(file), std::move(dataset), count, std::move(msg)});
  }
  std::size_t warnings() const;
  const CheckIssue* find(const std::string& dataset) const;  // first warning about dataset
  std::string str() const;
};

}  // namespace remnant::eos
