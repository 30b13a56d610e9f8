// Recovered primitives against the EOS evaluated independently (issue 20, item 4): the states are
// built at nodes of the reduced SFHo table read straight from its HDF5 datasets by this test
// (StellarCollapse: eps = 10^logenergy - energy_shift in erg/g; CompOSE: p = Q1 nb, eps = Q7), not
// through the EOS thorn. Round trips (prim -> cons -> prim with the same EOS object)
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
constexpr double kMeV_erg = 1.602176634e-6, kMeV_g = 1.782661921e-27, kFm3_cm3 = 1e-39;

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

// A table node in code units (T in MeV), from the file alone.
struct Node {
  double rho, T, ye, eps, press;
};

// Every third node in density and temperature, every fourth in Ye; the outermost nodes are left out
// (the recovery may clamp there by policy).
template <class F>
void for_sampled_nodes(std::size_t nr, std::size_t nt, std::size_t ny, F&& f) {
  for (std::size_t iy = 1; iy + 1 < ny; iy += 4)
    for (std::size_t it = 1; it + 1 < nt; it += 3)
      for (std::size_t ir = 1; ir + 1 < nr; ir += 3) f(ir, it, iy);
}

// StellarCollapse: [Ye][T][rho] datasets logpress (dyn/cm^2), logenergy = log10(eps + energy_shift)
// (erg/g); axes logrho (g/cm^3), logtemp (MeV), ye.
std::vector<Node> stellarcollapse_nodes(const std::string& path, double& shift) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << path;
  const auto logrho = read_dataset(f, "logrho"), logtemp = read_dataset(f, "logtemp"), ye = read_dataset(f, "ye");
  const auto logpress = read_dataset(f, "logpress"), logenergy = read_dataset(f, "logenergy");
  shift = read_dataset(f, "energy_shift").at(0);
  H5Fclose(f);
  std::vector<Node> nodes;
  for_sampled_nodes(logrho.size(), logtemp.size(), ye.size(), [&](std::size_t ir, std::size_t it, std::size_t iy) {
    const std::size_t q = (iy * logtemp.size() + it) * logrho.size() + ir;
    nodes.push_back({std::pow(10.0, logrho[ir]) / kDensity, std::pow(10.0, logtemp[it]), ye[iy],
                     (std::pow(10.0, logenergy[q]) - shift) / (kC * kC), std::pow(10.0, logpress[q]) / kPressure});
  });
  return nodes;
}

// CompOSE HDF5 (PyCompOSE): (nb, yq, t) datasets Q1 = p / nb (MeV), Q7 = e / (nb m_n) - 1; axes nb
// (fm^-3), t (MeV), yq; the neutron mass mn (MeV). rho = nb m_n, so eps = Q7.
std::vector<Node> compose_nodes(const std::string& path) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << path;
  const auto nb = read_dataset(f, "nb"), t = read_dataset(f, "t"), yq = read_dataset(f, "yq");
  const auto Q1 = read_dataset(f, "Q1"), Q7 = read_dataset(f, "Q7");
  const double mn = read_dataset(f, "mn").at(0);
  H5Fclose(f);
  std::vector<Node> nodes;
  for_sampled_nodes(nb.size(), t.size(), yq.size(), [&](std::size_t ir, std::size_t it, std::size_t iy) {
    const std::size_t q = (ir * yq.size() + iy) * t.size() + it;
    nodes.push_back({nb[ir] * mn * kMeV_g / kFm3_cm3 / kDensity, t[it], yq[iy], Q7[q],
                     Q1[q] * nb[ir] * kMeV_erg / kFm3_cm3 / kPressure});
  });
  return nodes;
}

struct Worst {
  int n = 0, failed = 0;
  double T = 0, p = 0, eps = 0;
};

// Moving, mildly magnetised states at the nodes on near-flat metrics, recovered with the EOS thorn's
// reading of the same file.
Worst recover_nodes(const std::string& path, const std::vector<Node>& nodes) {
  const eos::Tabulated<> e(eos::load_table(path));
  remnant::atmosphere::Atmosphere atm;
  atm.rho_thr = 1e-300;
  Settings s;
  s.policy.W_max = 1e300;
  c2p_test::Randomiser R(2020);
  Worst w;
  for (const Node& node : nodes) {
    Primitives orig;
    orig.rho = node.rho, orig.T = node.T, orig.ye = node.ye, orig.eps = node.eps, orig.press = node.press;
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
    ++w.n;
    if (recover(e, s, atm, g, c, got).status != Status::ok) {
      ++w.failed;
      continue;
    }
    w.T = std::max(w.T, c2p_test::rel_err(got.T, orig.T));
    w.p = std::max(w.p, c2p_test::rel_err(got.press, orig.press));
    w.eps = std::max(w.eps, std::abs(got.eps - orig.eps) / (std::abs(orig.eps) + 1e-3));
  }
  return w;
}

// Bounds from the measured errors: T inherits the 5e-9 root tolerance divided by d ln eps / d ln T
// (small at cold nodes), p and eps are near round-off. A table read wrongly misses by far more.
void expect_recovered(const char* name, const Worst& w) {
  std::printf("%s: %d table nodes, %d failed; max rel err T %.2e, p %.2e, eps %.2e (/(|eps| + 1e-3))\n", name, w.n,
              w.failed, w.T, w.p, w.eps);
  EXPECT_GT(w.n, 500) << name;
  EXPECT_EQ(w.failed, 0) << name;
  EXPECT_LT(w.T, 1e-4) << name;
  EXPECT_LT(w.p, 1e-8) << name;
  EXPECT_LT(w.eps, 1e-9) << name;
}

}  // namespace

// Measured: T 2.1e-5, p 3.3e-10, eps 2.5e-11. Without the energy shift (2e19 erg/g = 0.022 in eps)
// p is off by 97 % while every round trip still passes.
TEST(Con2PrimIndependentEos, RecoversTheStellarCollapseFileValuesAtNodes) {
  const std::string path = c2p_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
  REQUIRE_TABLE(path);
  double shift = 0;
  const std::vector<Node> nodes = stellarcollapse_nodes(path, shift);
  ASSERT_GT(shift, 0) << "the test needs a table with an energy shift";
  expect_recovered("SFHo StellarCollapse", recover_nodes(path, nodes));
}

TEST(Con2PrimIndependentEos, RecoversTheCompOSEFileValuesAtNodes) {
  const std::string path = c2p_test::shared_eos("SFHo_reduced_39r_39t_20y_compose.h5");
  REQUIRE_TABLE(path);
  expect_recovered("SFHo CompOSE HDF5", recover_nodes(path, compose_nodes(path)));
}
