#include "hdf5_file.hpp"

#include <sstream>

#include "EOS/errors.hpp"

namespace remnant::eos::detail {
namespace {

// HDF5 prints its error stack by default; we report our own messages instead.
struct QuietH5 {
  H5E_auto2_t fn = nullptr;
  void* data = nullptr;
  QuietH5() { H5Eget_auto2(H5E_DEFAULT, &fn, &data); H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
  ~QuietH5() { H5Eset_auto2(H5E_DEFAULT, fn, data); }
};

std::string shape_str(const std::vector<hsize_t>& s) {
  std::ostringstream o;
  o << "(";
  for (std::size_t i = 0; i < s.size(); ++i) o << (i ? ", " : "") << s[i];
  o << ")";
  return o.str();
}

}  // namespace

H5File::H5File(const std::string& path) : path_(path) {
  QuietH5 q;
  if (H5Fis_hdf5(path.c_str()) <= 0) throw TableError(path, "", "not an HDF5 file (or unreadable)");
  id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id_ < 0) throw TableError(path, "", "cannot open HDF5 file");
}

H5File::~H5File() {
  if (id_ >= 0) H5Fclose(id_);
}

bool H5File::has(const std::string& name) const {
  QuietH5 q;
  return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<hsize_t> H5File::shape(const std::string& name) const {
  QuietH5 q;
  if (!has(name)) throw TableError(path_, name, "dataset is missing");
  hid_t ds = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
  if (ds < 0) throw TableError(path_, name, "cannot open dataset");
  hid_t sp = H5Dget_space(ds);
  int nd = H5Sget_simple_extent_ndims(sp);
  std::vector<hsize_t> dims(nd > 0 ? nd : 0);
  if (nd > 0) H5Sget_simple_extent_dims(sp, dims.data(), nullptr);
  H5Sclose(sp);
  H5Dclose(ds);
  return dims;
}

std::vector<double> H5File::read(const std::string& name, const std::vector<hsize_t>& expect,
                                 bool allow_integer) const {
  auto dims = shape(name);
  if (!expect.empty() && dims != expect)
    throw TableError(path_, name, "has shape " + shape_str(dims) + ", expected " + shape_str(expect));
  QuietH5 q;
  hid_t ds = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
  hid_t type = H5Dget_type(ds);
  H5T_class_t cls = H5Tget_class(type);
  H5Tclose(type);
  if (cls != H5T_FLOAT && cls != H5T_INTEGER) {
    H5Dclose(ds);
    throw TableError(path_, name, "is not numeric");
  }
  if (cls == H5T_INTEGER && !allow_integer) {
    H5Dclose(ds);
    throw TableError(path_, name, "is stored as integers; expected floating-point values (float32/float64)");
  }
  hsize_t n = 1;
  for (auto d : dims) n *= d;
  std::vector<double> v(n);
  herr_t st = n ? H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) : 0;
  H5Dclose(ds);
  if (st < 0) throw TableError(path_, name, "read failed");
  return v;
}

double H5File::scalar(const std::string& name) const {
  auto v = read(name, {}, true);
  if (v.size() != 1) throw TableError(path_, name, "expected a single value, found " + std::to_string(v.size()));
  return v[0];
}

bool h5_has_dataset(const std::string& path, const std::string& name) {
  QuietH5 q;
  if (H5Fis_hdf5(path.c_str()) <= 0) return false;
  hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return false;
  bool r = H5Lexists(f, name.c_str(), H5P_DEFAULT) > 0;
  H5Fclose(f);
  return r;
}

}  // namespace remnant::eos::detail
