#pragma once
// Test helpers: where the shared tables are, synthetic tables, a small StellarCollapse writer.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "remnant_test/shared_tables.hpp"
#include "EOS/table.hpp"
#include "EOS/units.hpp"

namespace eos_test {

using remnant::test::shared_eos;

// A table whose interpolated quantities are linear in (ln rho, ln T, Ye).
struct Linear {
  double c0, cr, ct, cy;
  double operator()(double lr, double lt, double ye) const { return c0 + cr * lr + ct * lt + cy * ye; }
};
struct Synthetic {
  Linear logp{-20.0, 1.3, 0.4, -0.7}, logeps{-3.0, 0.05, 0.8, 0.3}, cs2{0.3, 0.004, 0.01, 0.1},
      s{2.0, -0.05, 0.9, 1.5}, mue{10.0, 3.0, 1.0, 40.0}, mup{-5.0, 0.5, 0.25, 8.0}, mun{3.0, 1.0, -0.5, -6.0};
  double eps_shift = 0.02;
  int nr = 12, nt = 9, ny = 7;
  double lr0 = std::log(1e-12), lr1 = std::log(1e-3), lt0 = std::log(0.05), lt1 = std::log(200.0);
  double y0 = 0.02, y1 = 0.58;

  double lr(int i) const { return lr0 + (lr1 - lr0) * i / (nr - 1); }
  double lt(int i) const { return lt0 + (lt1 - lt0) * i / (nt - 1); }
  double ye(int i) const { return y0 + (y1 - y0) * i / (ny - 1); }

  remnant::eos::RawTable raw() const {
    remnant::eos::RawTable r;
    r.file = "synthetic";
    r.format = "synthetic";
    for (int i = 0; i < nr; ++i) r.rho.push_back(std::exp(lr(i)));
    for (int i = 0; i < nt; ++i) r.T.push_back(std::exp(lt(i)));
    for (int i = 0; i < ny; ++i) r.ye.push_back(ye(i));
    r.eps_shift = eps_shift;
    const std::size_t n = r.size();
    for (auto* f : {&r.press, &r.eps, &r.cs2, &r.entropy, &r.mu_e, &r.mu_p, &r.mu_n}) f->v.resize(n);
    r.press.dataset = "press", r.eps.dataset = "eps", r.cs2.dataset = "cs2", r.entropy.dataset = "entropy";
    r.mu_e.dataset = "mu_e", r.mu_p.dataset = "mu_p", r.mu_n.dataset = "mu_n";
    std::size_t i = 0;
    for (int iy = 0; iy < ny; ++iy)
      for (int it = 0; it < nt; ++it)
        for (int ir = 0; ir < nr; ++ir, ++i) {
          const double a = lr(ir), b = lt(it), c = ye(iy);
          r.press.v[i] = std::exp(logp(a, b, c));
          r.eps.v[i] = std::exp(logeps(a, b, c)) - eps_shift;
          r.cs2.v[i] = cs2(a, b, c);
          r.entropy.v[i] = s(a, b, c);
          r.mu_e.v[i] = mue(a, b, c);
          r.mu_p.v[i] = mup(a, b, c);
          r.mu_n.v[i] = mun(a, b, c);
        }
    return r;
  }
};

// Writes a RawTable as a StellarCollapse HDF5 file (cgs, log10), for reader and check tests.
// `skip` names a dataset to leave out; `bad_shape` one to write with a wrong shape; `as_integer` one
// to store as int32 (rounded); `composition` adds Xa, Xh, Xn, Xp, Abar, Zbar (placeholders).
inline void write_stellarcollapse(const std::string& path, const remnant::eos::RawTable& r, double shift_cgs,
                                  const std::string& skip = "", const std::string& bad_shape = "",
                                  const std::string& as_integer = "", bool composition = false) {
  namespace u = remnant::units;
  hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hsize_t nr = r.rho.size(), nt = r.T.size(), ny = r.ye.size();
  auto put = [&](const std::string& name, const std::vector<double>& v, std::vector<hsize_t> dims) {
    if (name == skip) return;
    if (name == bad_shape) dims.back() -= 1;
    hid_t sp = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
    const bool integer = name == as_integer;
    hid_t ds = H5Dcreate2(f, name.c_str(), integer ? H5T_STD_I32LE : H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT,
                          H5P_DEFAULT);
    std::vector<int> iv(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) iv[k] = int(std::lround(v[k]));
    if (integer) H5Dwrite(ds, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, iv.data());
    else H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Dclose(ds);
    H5Sclose(sp);
  };
  std::vector<double> lr, lt, lp, le, cs2;
  for (double x : r.rho) lr.push_back(std::log10(x / u::rho_cgs_to_code));
  for (double x : r.T) lt.push_back(std::log10(x));
  for (double x : r.press.v) lp.push_back(std::log10(x / u::press_cgs_to_code));
  for (double x : r.eps.v) le.push_back(std::log10(x / u::eps_cgs_to_code + shift_cgs));
  for (double x : r.cs2.v) cs2.push_back(x / u::cs2_cgs_to_code);
  const std::vector<hsize_t> d3{ny, nt, nr};
  put("logrho", lr, {nr});
  put("logtemp", lt, {nt});
  put("ye", r.ye, {ny});
  put("logpress", lp, d3);
  put("logenergy", le, d3);
  put("cs2", cs2, d3);
  put("entropy", r.entropy.v, d3);
  put("mu_e", r.mu_e.v, d3);
  put("mu_p", r.mu_p.v, d3);
  put("mu_n", r.mu_n.v, d3);
  if (composition) {
    const std::size_t n = r.press.v.size();
    put("Xa", std::vector<double>(n, 0.1), d3);
    put("Xh", std::vector<double>(n, 0.2), d3);
    put("Xn", std::vector<double>(n, 0.4), d3);
    put("Xp", std::vector<double>(n, 0.3), d3);
    put("Abar", std::vector<double>(n, 56.0), d3);
    put("Zbar", std::vector<double>(n, 26.0), d3);
  }
  put("energy_shift", {shift_cgs}, {1});
  put("have_rel_cs2", {1.0}, {1});
  H5Fclose(f);
}

inline std::string temp_path(const std::string& name) {
  return (std::filesystem::path(testing::TempDir()) / name).string();
}

}  // namespace eos_test
