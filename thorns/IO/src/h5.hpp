#pragma once
// Thin RAII layer over the HDF5 C API for the IO thorn: handles that close themselves, errors
// that name the file and object, fixed-length strings (parallel HDF5 cannot write variable-length
// data), and hyperslab writes of one row per block.
#include <hdf5.h>
#include <mpi.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace remnant::io::h5 {

class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, -1)), close_(o.close_) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, -1);
      close_ = o.close_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t id() const { return id_; }
  operator hid_t() const { return id_; }
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = -1;
  }
  // Closes now and reports failure (a file close flushes: its error matters).
  void close_checked(const std::string& what);

 private:
  hid_t id_ = -1;
  Closer close_ = nullptr;
};

// Silences HDF5's own error printing for the lifetime of the object (we report errors ourselves).
class QuietErrors {
 public:
  QuietErrors();
  ~QuietErrors();
  QuietErrors(const QuietErrors&) = delete;
  QuietErrors& operator=(const QuietErrors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// Files. `comm` given: MPI-IO driver (collective); otherwise the POSIX driver of this process.
// user_block: bytes reserved at the start of the file that HDF5 never touches (0 or a power of 2 >= 512).
Handle create_file(const std::string& path, MPI_Comm comm, unsigned long long user_block = 0);
Handle create_file_serial(const std::string& path);
Handle open_file_serial(const std::string& path);

Handle create_group(hid_t loc, const std::string& name);
Handle open_group(hid_t loc, const std::string& name);
bool exists(hid_t loc, const std::string& path);

// Attributes: every rank of a parallel file must call these with the same values.
void write_attr(hid_t obj, const std::string& name, const std::string& value);
void write_attr(hid_t obj, const std::string& name, std::int64_t value);
void write_attr(hid_t obj, const std::string& name, double value);
void write_attr(hid_t obj, const std::string& name, const std::vector<std::int64_t>& values);
void write_attr(hid_t obj, const std::string& name, const std::vector<double>& values);
std::string read_attr_string(hid_t obj, const std::string& name);
std::int64_t read_attr_int(hid_t obj, const std::string& name);
double read_attr_double(hid_t obj, const std::string& name);
bool has_attr(hid_t obj, const std::string& name);

// Small datasets: created by every rank (collective metadata), data written only where
// `writer` is true (rank 0), with independent I/O.
void write_string(hid_t loc, const std::string& name, const std::string& text, bool writer);
void write_array(hid_t loc, const std::string& name, const std::vector<hsize_t>& shape,
                 const std::vector<double>& data, bool writer);
void write_array(hid_t loc, const std::string& name, const std::vector<hsize_t>& shape,
                 const std::vector<std::int64_t>& data, bool writer);
void write_array(hid_t loc, const std::string& name, const std::vector<hsize_t>& shape,
                 const std::vector<std::uint64_t>& data, bool writer);

std::string read_string(hid_t loc, const std::string& name);
std::vector<hsize_t> shape_of(hid_t loc, const std::string& name);
std::vector<double> read_doubles(hid_t loc, const std::string& name);
std::vector<std::int64_t> read_int64s(hid_t loc, const std::string& name);
std::vector<std::uint64_t> read_uint64s(hid_t loc, const std::string& name);

// A dataset of shape [rows] + row_shape; this rank writes the rows `rows` (sorted, ascending)
// from `data` (rows back to back) in one collective call. Every rank must call it.
void write_rows_collective(hid_t loc, const std::string& name, hsize_t total_rows,
                           const std::vector<hsize_t>& row_shape, const std::vector<hsize_t>& rows,
                           const double* data);
// Reads rows (any order) of a [rows] + row_shape double dataset, back to back, independently.
std::vector<double> read_rows(hid_t loc, const std::string& name, const std::vector<hsize_t>& rows);

}  // namespace remnant::io::h5
