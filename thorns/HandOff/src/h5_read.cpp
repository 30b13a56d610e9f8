#include "h5_read.hpp"

#include "remnant/error.hpp"

namespace remnant::handoff::h5 {

Handle open_file(const std::string& file) {
  Quiet q;
  Handle f(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!f.ok()) throw RunError("HandOff: cannot open the HDF5 file " + file + " (missing or not HDF5)");
  return f;
}

bool has_attr(hid_t obj, const char* name) { return H5Aexists(obj, name) > 0; }

namespace {
template <class T>
std::vector<T> attr_values(hid_t obj, const char* name, hid_t memtype, const std::string& file,
                           const std::string& object) {
  Quiet q;
  if (!has_attr(obj, name)) throw RunError("HandOff: " + file + ": '" + object + "' has no attribute '" + name + "'");
  Handle a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  Handle s(H5Aget_space(a), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(s);
  std::vector<T> v(static_cast<std::size_t>(n > 0 ? n : 0));
  if (n <= 0 || H5Aread(a, memtype, v.data()) < 0)
    throw RunError("HandOff: " + file + ": cannot read attribute '" + std::string(name) + "' of '" + object + "'");
  return v;
}
}  // namespace

std::vector<double> attr_doubles(hid_t obj, const char* name, const std::string& file, const std::string& object) {
  return attr_values<double>(obj, name, H5T_NATIVE_DOUBLE, file, object);
}
std::vector<long long> attr_ints(hid_t obj, const char* name, const std::string& file, const std::string& object) {
  return attr_values<long long>(obj, name, H5T_NATIVE_LLONG, file, object);
}

std::string attr_string(hid_t obj, const char* name, const std::string& file, const std::string& object) {
  Quiet q;
  if (!has_attr(obj, name)) throw RunError("HandOff: " + file + ": '" + object + "' has no attribute '" + name + "'");
  Handle a(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose);
  Handle t(H5Aget_type(a), H5Tclose);
  if (H5Tis_variable_str(t) > 0) {
    char* s = nullptr;
    Handle mt(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(mt, H5T_VARIABLE);
    if (H5Aread(a, mt, &s) < 0) throw RunError("HandOff: " + file + ": cannot read attribute '" + name + "'");
    std::string out = s ? s : "";
    H5free_memory(s);
    return out;
  }
  const std::size_t n = H5Tget_size(t) + 1;  // room for the terminator of a null-terminated memory string
  std::string out(n, '\0');
  Handle mt(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(mt, n);
  if (H5Aread(a, mt, out.data()) < 0) throw RunError("HandOff: " + file + ": cannot read attribute '" + name + "'");
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

std::vector<double> read_dataset(hid_t loc, const std::string& name, const std::string& file,
                                 std::vector<hsize_t>* shape) {
  Quiet q;
  Handle d(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.ok()) throw RunError("HandOff: " + file + ": no dataset '" + name + "'");
  Handle s(H5Dget_space(d), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(s);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank > 0 ? rank : 0));
  if (rank > 0) H5Sget_simple_extent_dims(s, dims.data(), nullptr);
  std::size_t n = 1;
  for (auto x : dims) n *= x;
  std::vector<double> v(n);
  if (n > 0 && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
    throw RunError("HandOff: " + file + ": cannot read dataset '" + name + "' as numbers");
  if (shape) *shape = dims;
  return v;
}

std::string read_string_dataset(hid_t loc, const std::string& name, const std::string& file) {
  Quiet q;
  Handle d(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.ok()) throw RunError("HandOff: " + file + ": no dataset '" + name + "'");
  Handle t(H5Dget_type(d), H5Tclose);
  Handle s(H5Dget_space(d), H5Sclose);
  if (H5Tget_class(t) != H5T_STRING) throw RunError("HandOff: " + file + ": '" + name + "' is not text");
  if (H5Tis_variable_str(t) > 0) {
    char* c = nullptr;
    Handle mt(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(mt, H5T_VARIABLE);
    if (H5Dread(d, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, &c) < 0) throw RunError("HandOff: " + file + ": cannot read '" + name + "'");
    std::string out = c ? c : "";
    H5free_memory(c);
    return out;
  }
  const std::size_t size = H5Tget_size(t) + 1;
  const hssize_t npts = H5Sget_simple_extent_npoints(s);
  std::string out(size * static_cast<std::size_t>(npts > 0 ? npts : 1), '\0');
  Handle mt(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(mt, size);
  if (H5Dread(d, mt, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw RunError("HandOff: " + file + ": cannot read '" + name + "'");
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

std::string read_text_dataset(hid_t loc, const std::string& name, const std::string& file) {
  Quiet q;
  Handle d(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.ok()) throw RunError("HandOff: " + file + ": no dataset '" + name + "'");
  Handle t(H5Dget_type(d), H5Tclose);
  if (H5Tget_class(t) == H5T_STRING) return read_string_dataset(loc, name, file);
  if (H5Tget_class(t) != H5T_INTEGER || H5Tget_size(t) != 1) throw RunError("HandOff: " + file + ": '" + name + "' is not text");
  Handle s(H5Dget_space(d), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(s);
  std::string out(static_cast<std::size_t>(n > 0 ? n : 0), '\0');
  if (n > 0 && H5Dread(d, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw RunError("HandOff: " + file + ": cannot read '" + name + "'");
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

bool exists(hid_t loc, const std::string& path) {
  Quiet q;
  return H5Lexists(loc, path.c_str(), H5P_DEFAULT) > 0;
}

std::vector<std::string> dataset_names(hid_t loc) {
  std::vector<std::string> names;
  auto cb = [](hid_t g, const char* name, const H5L_info_t*, void* data) -> herr_t {
    const hid_t o = H5Oopen(g, name, H5P_DEFAULT);
    if (o >= 0) {
      if (H5Iget_type(o) == H5I_DATASET) static_cast<std::vector<std::string>*>(data)->push_back(name);
      H5Oclose(o);
    }
    return 0;
  };
  Quiet q;
  H5Literate(loc, H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, cb, &names);
  return names;
}

}  // namespace remnant::handoff::h5
