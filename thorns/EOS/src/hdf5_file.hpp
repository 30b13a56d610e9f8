#pragma once
// Minimal read-only HDF5 access (C API) with errors that name the file and dataset.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace remnant::eos::detail {

class H5File {
 public:
  explicit H5File(const std::string& path);
  ~H5File();
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;

  const std::string& path() const { return path_; }
  bool has(const std::string& name) const;
  std::vector<hsize_t> shape(const std::string& name) const;
  // Reads a dataset as doubles; `expect` checks the shape when not empty. Integer datasets are an
  // error unless allow_integer (counts and flags may be integers; log10 values stored as integers
  // have lost their digits).
  std::vector<double> read(const std::string& name, const std::vector<hsize_t>& expect = {},
                           bool allow_integer = false) const;
  double scalar(const std::string& name) const;  // a 0-d or 1-element dataset

 private:
  std::string path_;
  hid_t id_ = -1;
};

// True if the file is an HDF5 file holding a dataset of this name (no exceptions).
bool h5_has_dataset(const std::string& path, const std::string& name);

}  // namespace remnant::eos::detail
