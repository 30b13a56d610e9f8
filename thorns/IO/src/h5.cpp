#include "h5.hpp"

#include <algorithm>
#include <numeric>

#include "remnant/error.hpp"

namespace remnant::io::h5 {

namespace {

// The descriptions on HDF5's error stack (innermost last), e.g. "truncated file: eof = ...".
herr_t collect(unsigned, const H5E_error2_t* e, void* out) {
  auto& s = *static_cast<std::string*>(out);
  if (s.empty() && e->desc && *e->desc) s = e->desc;  // the innermost entry: the most specific cause
  return 0;
}

[[noreturn]] void fail(const std::string& what) {
  std::string cause;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, collect, &cause);
  H5Eclear2(H5E_DEFAULT);
  throw RunError("HDF5: " + what + (cause.empty() ? "" : " (" + cause + ")"));
}

hid_t checked(hid_t id, const std::string& what) {
  if (id < 0) fail(what);
  return id;
}

void checked_status(herr_t s, const std::string& what) {
  if (s < 0) fail(what);
}

Handle string_type(std::size_t size) {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(t, std::max<std::size_t>(size, 1));
  H5Tset_strpad(t, H5T_STR_NULLPAD);
  return t;
}

Handle simple_space(const std::vector<hsize_t>& shape) {
  if (shape.empty()) return Handle(H5Screate(H5S_SCALAR), H5Sclose);
  return Handle(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose);
}

template <class T>
void write_attr_array(hid_t obj, const std::string& name, hid_t type, const std::vector<T>& v) {
  Handle space = simple_space({static_cast<hsize_t>(v.size())});
  Handle a(checked(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), "create attribute " + name),
           H5Aclose);
  checked_status(H5Awrite(a, type, v.data()), "write attribute " + name);
}

template <class T>
void write_array_t(hid_t loc, const std::string& name, const std::vector<hsize_t>& shape, const std::vector<T>& data,
                   bool writer, hid_t mem_type, hid_t file_type) {
  Handle space = simple_space(shape);
  Handle d(checked(H5Dcreate2(loc, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   "create dataset " + name),
           H5Dclose);
  const hsize_t n = std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<>());
  if (writer && n > 0) {
    if (data.size() != n) throw RunError("HDF5: dataset " + name + ": data size does not match its shape");
    checked_status(H5Dwrite(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "write dataset " + name);
  }
}

template <class T>
std::vector<T> read_all(hid_t loc, const std::string& name, hid_t mem_type) {
  Handle d(checked(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "open dataset " + name), H5Dclose);
  Handle space(H5Dget_space(d), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> out(static_cast<std::size_t>(std::max<hssize_t>(n, 0)));
  if (!out.empty()) checked_status(H5Dread(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read dataset " + name);
  return out;
}

}  // namespace

void Handle::close_checked(const std::string& what) {
  if (id_ < 0) return;
  const herr_t s = close_ ? close_(id_) : 0;
  id_ = -1;
  checked_status(s, "close " + what);
}

QuietErrors::QuietErrors() {
  H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}
QuietErrors::~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

Handle create_file(const std::string& path, MPI_Comm comm, unsigned long long user_block) {
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  checked_status(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL), "MPI-IO driver for " + path);
  // Metadata written collectively: one writer instead of every rank touching small objects.
  H5Pset_coll_metadata_write(fapl, true);
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  if (user_block) checked_status(H5Pset_userblock(fcpl, user_block), "user block of " + path);
  return Handle(checked(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl, fapl), "create " + path), H5Fclose);
}

Handle create_file_serial(const std::string& path) {
  return Handle(checked(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "create " + path), H5Fclose);
}

Handle open_file_serial(const std::string& path) {
  return Handle(checked(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open " + path), H5Fclose);
}

Handle create_group(hid_t loc, const std::string& name) {
  return Handle(checked(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "create group " + name),
                H5Gclose);
}

Handle open_group(hid_t loc, const std::string& name) {
  return Handle(checked(H5Gopen2(loc, name.c_str(), H5P_DEFAULT), "open group " + name), H5Gclose);
}

bool exists(hid_t loc, const std::string& path) {
  // Check each link on the way so that a missing parent is "false", not an error.
  std::string partial;
  std::size_t pos = 0;
  while (pos <= path.size()) {
    const std::size_t next = path.find('/', pos);
    partial = path.substr(0, next == std::string::npos ? path.size() : next);
    if (!partial.empty() && partial != "/" && H5Lexists(loc, partial.c_str(), H5P_DEFAULT) <= 0) return false;
    if (next == std::string::npos) break;
    pos = next + 1;
  }
  return true;
}

void write_attr(hid_t obj, const std::string& name, const std::string& value) {
  Handle t = string_type(value.size());
  Handle space = simple_space({});
  Handle a(checked(H5Acreate2(obj, name.c_str(), t, space, H5P_DEFAULT, H5P_DEFAULT), "create attribute " + name),
           H5Aclose);
  std::string padded = value;
  padded.resize(std::max<std::size_t>(value.size(), 1), '\0');
  checked_status(H5Awrite(a, t, padded.data()), "write attribute " + name);
}
void write_attr(hid_t obj, const std::string& name, std::int64_t value) {
  write_attr(obj, name, std::vector<std::int64_t>{value});
}
void write_attr(hid_t obj, const std::string& name, double value) { write_attr(obj, name, std::vector<double>{value}); }
void write_attr(hid_t obj, const std::string& name, const std::vector<std::int64_t>& values) {
  write_attr_array(obj, name, H5T_NATIVE_INT64, values);
}
void write_attr(hid_t obj, const std::string& name, const std::vector<double>& values) {
  write_attr_array(obj, name, H5T_NATIVE_DOUBLE, values);
}

bool has_attr(hid_t obj, const std::string& name) { return H5Aexists(obj, name.c_str()) > 0; }

std::string read_attr_string(hid_t obj, const std::string& name) {
  Handle a(checked(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "open attribute " + name), H5Aclose);
  Handle ft(H5Aget_type(a), H5Tclose);
  if (H5Tget_class(ft) != H5T_STRING || H5Tis_variable_str(ft) > 0) throw RunError("HDF5: attribute " + name + " is not a fixed-length string");
  const std::size_t size = H5Tget_size(ft);
  Handle t = string_type(size);
  std::string s(size, '\0');
  checked_status(H5Aread(a, t, s.data()), "read attribute " + name);
  s.resize(s.find('\0') == std::string::npos ? s.size() : s.find('\0'));
  return s;
}

std::int64_t read_attr_int(hid_t obj, const std::string& name) {
  Handle a(checked(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "open attribute " + name), H5Aclose);
  std::int64_t v = 0;
  checked_status(H5Aread(a, H5T_NATIVE_INT64, &v), "read attribute " + name);
  return v;
}

double read_attr_double(hid_t obj, const std::string& name) {
  Handle a(checked(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "open attribute " + name), H5Aclose);
  double v = 0;
  checked_status(H5Aread(a, H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  return v;
}

void write_string(hid_t loc, const std::string& name, const std::string& text, bool writer) {
  Handle t = string_type(text.size());
  Handle space = simple_space({});
  Handle d(checked(H5Dcreate2(loc, name.c_str(), t, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   "create dataset " + name),
           H5Dclose);
  if (writer) {
    std::string padded = text;
    padded.resize(std::max<std::size_t>(text.size(), 1), '\0');
    checked_status(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, padded.data()), "write dataset " + name);
  }
}

void write_array(hid_t loc, const std::string& name, const std::vector<hsize_t>& shape, const std::vector<double>& data,
                 bool writer) {
  write_array_t(loc, name, shape, data, writer, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
}
void write_array(hid_t loc, const std::string& name, const std::vector<hsize_t>& shape,
                 const std::vector<std::int64_t>& data, bool writer) {
  write_array_t(loc, name, shape, data, writer, H5T_NATIVE_INT64, H5T_STD_I64LE);
}
void write_array(hid_t loc, const std::string& name, const std::vector<hsize_t>& shape,
                 const std::vector<std::uint64_t>& data, bool writer) {
  write_array_t(loc, name, shape, data, writer, H5T_NATIVE_UINT64, H5T_STD_U64LE);
}

std::string read_string(hid_t loc, const std::string& name) {
  Handle d(checked(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "open dataset " + name), H5Dclose);
  Handle ft(H5Dget_type(d), H5Tclose);
  if (H5Tget_class(ft) != H5T_STRING || H5Tis_variable_str(ft) > 0) throw RunError("HDF5: dataset " + name + " is not a fixed-length string");
  const std::size_t size = H5Tget_size(ft);
  Handle t = string_type(size);
  std::string s(size, '\0');
  checked_status(H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, s.data()), "read dataset " + name);
  s.resize(s.find('\0') == std::string::npos ? s.size() : s.find('\0'));
  return s;
}

std::vector<hsize_t> shape_of(hid_t loc, const std::string& name) {
  Handle d(checked(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "open dataset " + name), H5Dclose);
  Handle space(H5Dget_space(d), H5Sclose);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(H5Sget_simple_extent_ndims(space), 0)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return dims;
}

std::vector<double> read_doubles(hid_t loc, const std::string& name) { return read_all<double>(loc, name, H5T_NATIVE_DOUBLE); }
std::vector<std::int64_t> read_int64s(hid_t loc, const std::string& name) {
  return read_all<std::int64_t>(loc, name, H5T_NATIVE_INT64);
}
std::vector<std::uint64_t> read_uint64s(hid_t loc, const std::string& name) {
  return read_all<std::uint64_t>(loc, name, H5T_NATIVE_UINT64);
}

void write_rows_collective(hid_t loc, const std::string& name, hsize_t total_rows, const std::vector<hsize_t>& row_shape,
                           const std::vector<hsize_t>& rows, const double* data) {
  std::vector<hsize_t> shape{total_rows};
  shape.insert(shape.end(), row_shape.begin(), row_shape.end());
  const hsize_t row_size = std::accumulate(row_shape.begin(), row_shape.end(), hsize_t{1}, std::multiplies<>());
  Handle fspace = simple_space(shape);
  Handle d(checked(H5Dcreate2(loc, name.c_str(), H5T_IEEE_F64LE, fspace, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   "create dataset " + name),
           H5Dclose);
  // Consecutive rows merge into one hyperslab: a rank's blocks are usually one contiguous range.
  H5Sselect_none(fspace);
  std::vector<hsize_t> start(shape.size(), 0), count = shape;
  for (std::size_t r = 0; r < rows.size();) {
    std::size_t e = r + 1;
    while (e < rows.size() && rows[e] == rows[e - 1] + 1) ++e;
    start[0] = rows[r];
    count[0] = static_cast<hsize_t>(e - r);
    checked_status(H5Sselect_hyperslab(fspace, H5S_SELECT_OR, start.data(), nullptr, count.data(), nullptr),
                   "select rows of " + name);
    r = e;
  }
  const hsize_t n = static_cast<hsize_t>(rows.size()) * row_size;
  Handle mspace(H5Screate_simple(1, std::vector<hsize_t>{std::max<hsize_t>(n, 1)}.data(), nullptr), H5Sclose);
  if (n == 0) H5Sselect_none(mspace);
  Handle xfer(H5Pcreate(H5P_DATASET_XFER), H5Pclose);
  H5Pset_dxpl_mpio(xfer, H5FD_MPIO_COLLECTIVE);
  static const double dummy = 0;
  checked_status(H5Dwrite(d, H5T_NATIVE_DOUBLE, mspace, fspace, xfer, n ? data : &dummy), "write dataset " + name);
}

std::vector<double> read_rows(hid_t loc, const std::string& name, const std::vector<hsize_t>& rows) {
  Handle d(checked(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "open dataset " + name), H5Dclose);
  Handle fspace(H5Dget_space(d), H5Sclose);
  const int nd = H5Sget_simple_extent_ndims(fspace);
  std::vector<hsize_t> shape(static_cast<std::size_t>(std::max(nd, 1)));
  H5Sget_simple_extent_dims(fspace, shape.data(), nullptr);
  hsize_t row_size = 1;
  for (std::size_t i = 1; i < shape.size(); ++i) row_size *= shape[i];
  std::vector<double> out(rows.size() * row_size);
  std::vector<hsize_t> start(shape.size(), 0), count = shape;
  count[0] = 1;
  Handle mspace(H5Screate_simple(1, &row_size, nullptr), H5Sclose);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (rows[r] >= shape[0]) throw RunError("HDF5: dataset " + name + " has no row " + std::to_string(rows[r]));
    start[0] = rows[r];
    H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
    checked_status(H5Dread(d, H5T_NATIVE_DOUBLE, mspace, fspace, H5P_DEFAULT, out.data() + r * row_size),
                   "read row " + std::to_string(rows[r]) + " of " + name);
  }
  return out;
}

}  // namespace remnant::io::h5
