#include "synthetic_carpet.hpp"

#include <hdf5.h>

#include <cmath>
#include <limits>
#include <string>
#include <stdexcept>

namespace remnant::handoff::synthetic {
namespace {

void attr(hid_t obj, const char* name, hid_t type, const void* data, hsize_t n) {
  const hid_t s = H5Screate_simple(1, &n, nullptr);
  const hid_t a = H5Acreate2(obj, name, type, s, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, type, data);
  H5Aclose(a), H5Sclose(s);
}

void write_bytes(hid_t file, const std::string& group, const std::string& name, const std::string& text) {
  const hid_t g = H5Gcreate2(file, group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t n = text.size();
  const hid_t s = H5Screate_simple(1, &n, nullptr);
  const hid_t d = H5Dcreate2(g, name.c_str(), H5T_NATIVE_UCHAR, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data());
  H5Dclose(d), H5Sclose(s), H5Gclose(g);
}

void write_text(hid_t file, const std::string& group, const std::string& name, const std::string& text) {
  const hid_t g = H5Gcreate2(file, group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, text.size() + 1);
  const hid_t s = H5Screate(H5S_SCALAR);
  const hid_t d = H5Dcreate2(g, name.c_str(), t, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.c_str());
  H5Dclose(d), H5Sclose(s), H5Tclose(t), H5Gclose(g);
}

}  // namespace

std::vector<std::string> write_synthetic_carpet(const std::string& dir, const SyntheticCarpet& spec, const Field& f,
                                                bool write) {
  std::vector<std::string> paths{dir + "/" + spec.stem + ".file_0.h5", dir + "/" + spec.stem + ".file_1.h5"};
  if (!write) return paths;
  hid_t files[2];
  for (int i = 0; i < 2; ++i) {
    files[i] = H5Fcreate(paths[static_cast<std::size_t>(i)].c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (files[i] < 0) throw std::runtime_error("cannot create " + paths[static_cast<std::size_t>(i)]);
  }
  if (spec.write_parameters) {
    std::string text = "Carpet::domain_from_coordbase = \"yes\"\n";
    for (int d = 0; d < 3; ++d)
      text += std::string("ReflectionSymmetry::reflection_") + static_cast<char>('x' + d) + " = \"" +
              (spec.reflection[static_cast<std::size_t>(d)] ? "yes" : "no") + "\"\n";
    if (!spec.ghosts_written) text += "CarpetIOHDF5::" + spec.ghosts_parameter + " = \"no\"\n";
    text += spec.extra_parameters;
    (spec.parameters_as_bytes ? write_bytes : write_text)(files[0], "Parameters and Global Attributes", "All Parameters", text);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int ng = spec.ghosts_written ? spec.ghosts : 0, nb = spec.buffer;
  for (std::size_t l = 0; l < spec.levels.size(); ++l) {
    const LevelLayout& L = spec.levels[l];
    const int half = L.nodes[static_cast<std::size_t>(L.split_dir)] / 2;
    for (int c = 0; c < 2; ++c) {
      // Component's interior node range, then its extent with ghosts and buffers.
      std::array<int, 3> ilo{0, 0, 0}, ihi{}, lo{}, hi{};
      for (std::size_t d = 0; d < 3; ++d) ihi[d] = L.nodes[d] - 1;
      const auto sd = static_cast<std::size_t>(L.split_dir);
      if (c == 0) ihi[sd] = half - 1;
      else ilo[sd] = half;
      for (std::size_t d = 0; d < 3; ++d) {
        const bool box_lo = ilo[d] == 0, box_hi = ihi[d] == L.nodes[d] - 1;
        const int edge = l == 0 ? 0 : nb + ng;
        lo[d] = ilo[d] - (box_lo ? (spec.reflection[d] ? ng : edge) : ng);
        hi[d] = ihi[d] + (box_hi ? edge : ng);
      }
      const std::array<int, 3> n{hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1};
      for (const auto& var : spec.variables) {
        const auto found = spec.iterations_of.find(var);
        std::vector<std::int64_t> its = found != spec.iterations_of.end() ? found->second : spec.iterations;
        const auto extra = spec.extra_iterations_of_level.find(static_cast<int>(l));
        if (extra != spec.extra_iterations_of_level.end()) its.insert(its.end(), extra->second.begin(), extra->second.end());
        for (const std::int64_t it : its) {
          std::vector<double> data(static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]));
          std::size_t q = 0;
          for (int k = lo[2]; k <= hi[2]; ++k)
            for (int j = lo[1]; j <= hi[1]; ++j)
              for (int i = lo[0]; i <= hi[0]; ++i, ++q) {
                const std::array<int, 3> m{i, j, k};
                bool ghost = false, buffer = false;
                for (std::size_t d = 0; d < 3; ++d) {
                  if (m[d] < 0 || m[d] >= L.nodes[d]) {  // outside the level's box
                    const int dist = m[d] < 0 ? -m[d] : m[d] - L.nodes[d] + 1;
                    if ((m[d] < 0 && spec.reflection[d]) || dist > nb) ghost = true;
                    else buffer = true;
                  } else if (m[d] < ilo[d] || m[d] > ihi[d]) {
                    ghost = true;  // inter-component ghost
                  }
                }
                const double x = L.first[0] + i * L.h, y = L.first[1] + j * L.h, z = L.first[2] + k * L.h;
                data[q] = ghost ? nan : f(var, static_cast<int>(l), x, y, z) + (buffer ? 0.5 : 0.0);
              }
          const std::string name = var + " it=" + std::to_string(it) + " tl=0 rl=" + std::to_string(l) + " c=" + std::to_string(c);
          const hsize_t dims[3] = {static_cast<hsize_t>(n[2]), static_cast<hsize_t>(n[1]), static_cast<hsize_t>(n[0])};
          const hid_t file = files[c % 2];
          const hid_t s = H5Screate_simple(3, dims, nullptr);
          const hid_t d = H5Dcreate2(file, name.c_str(), H5T_NATIVE_DOUBLE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
          H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
          const double origin[3] = {L.first[0] + lo[0] * L.h, L.first[1] + lo[1] * L.h, L.first[2] + lo[2] * L.h};
          const double delta[3] = {L.h, L.h, L.h};
          const int iorigin[3] = {lo[0], lo[1], lo[2]};
          const int ghosts[3] = {spec.ghosts, spec.ghosts, spec.ghosts};  // the grid's, written or not
          const int level = static_cast<int>(l);
          if (spec.write_bbox) {  // [x lower, x upper, y lower, ...]
            int bbox[6];
            for (std::size_t a = 0; a < 3; ++a) {
              bbox[2 * a] = ilo[a] == 0 && (l == 0 || spec.reflection[a]) ? 1 : 0;
              bbox[2 * a + 1] = ihi[a] == L.nodes[a] - 1 && l == 0 ? 1 : 0;
            }
            attr(d, "cctk_bbox", H5T_NATIVE_INT, bbox, 6);
          }
          if (spec.write_active) {  // as CarpetIOHDF5: a bboxset in units of the finest level's spacing
            const int st = 1 << (spec.levels.size() - 1 - l);
            std::string box = "bboxset<CCTK_INT4,3>(set<bbox>:{([";
            for (std::size_t a = 0; a < 3; ++a) box += std::to_string(ilo[a] * st) + (a < 2 ? "," : "]:[");
            for (std::size_t a = 0; a < 3; ++a) box += std::to_string(ihi[a] * st) + (a < 2 ? "," : "]:[");
            for (std::size_t a = 0; a < 3; ++a) box += std::to_string(st) + (a < 2 ? "," : "]/...)},stride:[1,1,1],offset:[0,0,0])");
            const hid_t t = H5Tcopy(H5T_C_S1);
            H5Tset_size(t, box.size());
            const hid_t sc = H5Screate(H5S_SCALAR);
            const hid_t a = H5Acreate2(d, "active", t, sc, H5P_DEFAULT, H5P_DEFAULT);
            H5Awrite(a, t, box.data());
            H5Aclose(a), H5Sclose(sc), H5Tclose(t);
          }
          attr(d, "origin", H5T_NATIVE_DOUBLE, origin, 3);
          attr(d, "delta", H5T_NATIVE_DOUBLE, delta, 3);
          attr(d, "iorigin", H5T_NATIVE_INT, iorigin, 3);
          attr(d, "cctk_nghostzones", H5T_NATIVE_INT, ghosts, 3);
          attr(d, "level", H5T_NATIVE_INT, &level, 1);
          attr(d, "time", H5T_NATIVE_DOUBLE, &spec.time, 1);
          H5Dclose(d), H5Sclose(s);
        }
      }
    }
  }
  for (hid_t file : files) H5Fclose(file);
  return paths;
}

}  // namespace remnant::handoff::synthetic
