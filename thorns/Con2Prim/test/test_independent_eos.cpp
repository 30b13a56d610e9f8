// Recovered primitives against the EOS evaluated independently (issue 20, item 4): the states are
// built at nodes of the reduced SFHo table read straight from its HDF5 datasets by this test
// (logrho, logtemp, ye, logpress, logenergy, energy_shift; eps = 10^logenergy - energy_shift in
// erg/g), not through the EOS thorn. Round trips (prim -> cons -> prim with the same EOS object)
// cannot see an EOS that reads the table wrongly; here the recovery, run with the EOS thorn's
// table, must return the file's T and p for the file's eps. At a node the thorn's interpolation is
// exact, so the only errors are the recovery's.
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/prim_to_cons.hpp"
#include "Con2Prim/recover.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "c2p_test_util.hpp"

using namespace remnant::con2prim;
namespace eos = remnant::eos;

namespace {

// Code units (G = c = M_sun = 1) from cgs, written out here rather than taken from EOS/units.hpp.
constexpr double kC = 2.99792458e10, kG = 6.67430e-8, kGMsun = 1.3271244e26;
constexpr double kLength = kGMsun / (kC * kC), kMsun = kGMsun / kG;
constexpr double kDensity = kMsun / (kLength * kLength * kLength), kPressure = kDensity * kC * kC;

std::vector<double> read_dataset(hid_t file, const char* name) {
  const hid_t d = H5Dopen2(file, name, H5P_DEFAULT);
  EXPECT_GE(d, 0) << name;
  const hid_t space = H5Dget_space(d);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<double> v(static_cast<std::size_t>(n));
  EXPECT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0) << name;
  H5Sclose(space);
  H5Dclose(d);
  return v;
}

struct FileTable {
  std::vector<double> logrho, logtemp, ye, logpress, logenergy;
  double shift = 0;
  std::size_t at(std::size_t ir, std::size_t it, std::size_t iy) const {  // [Ye][T][rho]
    return (iy * logtemp.size() + it) * logrho.size() + ir;
  }
};

FileTable read_file(const std::string& path) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << path;
  FileTable t;
  t.logrho = read_dataset(f, "logrho");
  t.logtemp = read_dataset(f, "logtemp");
  t.ye = read_dataset(f, "ye");
  t.logpress = read_dataset(f, "logpress");
  t.logenergy = read_dataset(f, "logenergy");
  t.shift = read_dataset(f, "energy_shift").at(0);
  H5Fclose(f);
  return t;
}

}  // namespace

TEST(Con2PrimIndependentEos, RecoversTheTableFileValuesAtNodes) {
  const std::string path = c2p_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
  REQUIRE_TABLE(path);
  const FileTable file = read_file(path);
  ASSERT_GT(file.shift, 0) << "the test needs a table with an energy shift";
  const eos::Tabulated<> e(eos::load_table(path));
  remnant::atmosphere::Atmosphere atm;
  atm.rho_thr = 1e-300;
  Settings s;
  s.policy.W_max = 1e300;
  c2p_test::Randomiser R(2020);
  int n = 0, failed = 0;
  double worst_T = 0, worst_p = 0, worst_eps = 0;
  // Every third node in rho and T, every fourth in Ye; the table's outermost nodes are left out
  // (the recovery may clamp there by policy).
  for (std::size_t iy = 1; iy + 1 < file.ye.size(); iy += 4)
    for (std::size_t it = 1; it + 1 < file.logtemp.size(); it += 3)
      for (std::size_t ir = 1; ir + 1 < file.logrho.size(); ir += 3) {
        const std::size_t q = file.at(ir, it, iy);
        Primitives orig;
        orig.rho = std::pow(10.0, file.logrho[ir]) / kDensity;
        orig.T = std::pow(10.0, file.logtemp[it]);
        orig.ye = file.ye[iy];
        orig.eps = (std::pow(10.0, file.logenergy[q]) - file.shift) / (kC * kC);
        orig.press = std::pow(10.0, file.logpress[q]) / kPressure;
        // A moving, mildly magnetised state on a near-flat metric.
        const Metric3 g = R.metric();
        orig.W = R.log_uniform(1.0, 5.0);
        const Vec3 dir = R.direction();
        const double speed = std::sqrt((orig.W - 1) * (orig.W + 1)) / orig.W, vn = std::sqrt(g.norm2_up(dir));
        for (int i = 0; i < 3; ++i) orig.v[i] = speed * dir[i] / vn;
        const Vec3 bdir = R.direction();
        const double bn = std::sqrt(g.norm2_up(bdir)), B = std::sqrt(1e-3 * orig.press) * orig.W;
        for (int i = 0; i < 3; ++i) orig.B[i] = B * bdir[i] / bn;
        Conserved c = prim_to_cons(orig, g);
        Primitives got;
        const Report r = recover(e, s, atm, g, c, got);
        ++n;
        if (r.status != Status::ok) {
          ++failed;
          continue;
        }
        worst_T = std::max(worst_T, c2p_test::rel_err(got.T, orig.T));
        worst_p = std::max(worst_p, c2p_test::rel_err(got.press, orig.press));
        worst_eps = std::max(worst_eps, std::abs(got.eps - orig.eps) / (std::abs(orig.eps) + 1e-3));
      }
  std::printf("%d table nodes (energy_shift %.4e erg/g): %d failed; max rel err T %.2e, p %.2e, eps %.2e (/(|eps| + 1e-3))\n",
              n, file.shift, failed, worst_T, worst_p, worst_eps);
  EXPECT_EQ(failed, 0);
  // Measured: T 2.1e-5 (cold nodes, where eps hardly depends on T: T inherits the 5e-9 root
  // tolerance divided by d ln eps / d ln T), p 3.3e-10, eps 2.5e-11. Bounds 5x, 30x and 40x that;
  // a table read without its energy shift (2e19 erg/g = 0.022 in eps) misses by orders of magnitude.
  EXPECT_LT(worst_T, 1e-4);
  EXPECT_LT(worst_p, 1e-8);
  EXPECT_LT(worst_eps, 1e-9);
}
