#pragma once
// EOS errors. Every message names the file and, where one is involved, the dataset.
#include <stdexcept>
#include <string>

namespace remnant::eos {

class EosError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A problem with a table file: missing, unreadable, mis-shaped or unphysical data.
class TableError : public EosError {
 public:
  TableError(const std::string& file, const std::string& dataset, const std::string& what)
      : EosError(file + (dataset.empty() ? "" : " [" + dataset + "]") + ": " + what),
        file_(file), dataset_(dataset) {}
  const std::string& file() const { return file_; }
  const std::string& dataset() const { return dataset_; }

 private:
  std::string file_, dataset_;
};

}  // namespace remnant::eos
