#pragma once
// Small read-only helpers over the HDF5 C API for the HandOff readers: handles that close
// themselves, attributes and whole datasets as doubles, errors that name the file and object.
#include <hdf5.h>

#include <string>
#include <utility>
#include <vector>

namespace remnant::handoff::h5 {

class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, -1)), close_(o.close_) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  operator hid_t() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  Closer close_;
};

// Silences HDF5's error stack printing while alive (we report errors ourselves).
class Quiet {
 public:
  Quiet() { H5Eget_auto2(H5E_DEFAULT, &f_, &d_), H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
  ~Quiet() { H5Eset_auto2(H5E_DEFAULT, f_, d_); }
  Quiet(const Quiet&) = delete;
  Quiet& operator=(const Quiet&) = delete;

 private:
  H5E_auto2_t f_ = nullptr;
  void* d_ = nullptr;
};

// Throw RunError naming `file` when something is missing or unreadable.
Handle open_file(const std::string& file);
bool has_attr(hid_t obj, const char* name);
std::vector<double> attr_doubles(hid_t obj, const char* name, const std::string& file, const std::string& object);
std::vector<long long> attr_ints(hid_t obj, const char* name, const std::string& file, const std::string& object);
std::string attr_string(hid_t obj, const char* name, const std::string& file, const std::string& object);
// The dataset's shape (slowest first) and all of its values as doubles.
std::vector<double> read_dataset(hid_t loc, const std::string& name, const std::string& file,
                                 std::vector<hsize_t>* shape = nullptr);
std::string read_string_dataset(hid_t loc, const std::string& name, const std::string& file);
// A string dataset, or a 1-byte integer array holding text (Carpet's parameter dump).
std::string read_text_dataset(hid_t loc, const std::string& name, const std::string& file);
bool exists(hid_t loc, const std::string& path);
// Names of the datasets directly under loc.
std::vector<std::string> dataset_names(hid_t loc);

}  // namespace remnant::handoff::h5
