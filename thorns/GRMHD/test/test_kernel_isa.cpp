// The hydro and MHD sweeps (pass 1) and the 3D Cartesian source rows (pass 2) run in an AVX2 version where
// the CPU has AVX2 (kernel_isa.hpp). Both versions must give the same bits: random primitives and
// metric (with shift) on a 3D Cartesian block, the fluxes and cons_rhs of the AVX2 and the portable
// kernels compared bit for bit, with the ideal gas (pressure reconstructed), a polytrope (the face
// thermodynamics from the EOS) and, where the shared table is present, SFHo (temperature and Ye);
// with a random field: the MHD fluxes, the EMF Riemann data (ct), the magnetised sources and the
// Cartesian uct_hll EMF rows.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "EOS/eos.hpp"
#include "kernel_block.hpp"
#include "constrained_transport.hpp"
#include "kernel_isa.hpp"
#include "mhd_fluxes.hpp"
#include "rhs.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;

// Primitives near rho0 (a table's range for SFHo), moving up to 0.3 c, and a metric with shift.
void fill(Block& b, const Groups& g, double rho0, double t0, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto component = [&](int group, int c, auto value) { test::fill_component(b, group, c, value); };
  for (int c = 0; c < Prim::ncomp; ++c) component(g.prim, c, [&] { return 0.1 + u(rng); });
  component(g.prim, Prim::idx::rho, [&] { return rho0 * (0.5 + u(rng)); });
  component(g.prim, Prim::idx::press, [&] { return 0.1 * rho0 * (0.5 + u(rng)); });
  component(g.prim, Prim::idx::temperature, [&] { return t0 * (0.5 + u(rng)); });
  component(g.prim, Prim::idx::Ye, [&] { return 0.1 + 0.3 * u(rng); });
  for (int c : {int{Prim::idx::vel}, int{Prim::idx::vel2}, int{Prim::idx::vel3}})
    component(g.prim, c, [&] { return 0.6 * (u(rng) - 0.5); });
  component(g.prim, Prim::idx::W, [&] { return 1.0 + 0.3 * u(rng); });
  component(g.metric, Metric::idx::psi, [&] { return 1.0 + 0.2 * u(rng); });
  component(g.metric, Metric::idx::alpha, [&] { return 0.6 + 0.4 * u(rng); });
  for (int c : {int{Metric::idx::beta}, int{Metric::idx::beta2}, int{Metric::idx::beta3}})
    component(g.metric, c, [&] { return 0.2 * (u(rng) - 0.5); });
}

std::vector<double> copy(Block& b, int group) {
  return {b.data(group), b.data(group) + b.size(group)};
}

int differing(const std::vector<double>& a, const std::vector<double>& c) {
  int n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(c[i]);
  return n;
}

// mhd: with a random field (face and cell-centred), the MHD sweep with `emfs` and the magnetised sources.
void expect_same_bits(const eos::EOS& eos, double rho0, double t0, std::uint64_t seed, bool mhd = false,
                      EmfScheme emfs = EmfScheme::uct_hll) {
  if (!avx2_kernels()) GTEST_SKIP() << "this CPU (or build) has no run-time AVX2 kernels: one version only";
  const VariableRegistry vars = test::kernel_registry();
  const Groups g = test::hydro_groups(vars);
  const MhdGroups mg = test::mhd_groups(vars);
  const std::unique_ptr<Block> block = test::kernel_block(vars, 12);
  Block& b = *block;
  fill(b, g, rho0, t0, seed);
  if (mhd) {
    std::mt19937_64 rng(seed + 100);
    std::uniform_real_distribution<double> u(-0.02, 0.02);
    for (int group : {mg.bface[0], mg.bface[1], mg.bface[2], mg.bvec})
      for (std::size_t i = 0; i < b.size(group); ++i) b.data(group)[i] = u(rng);
  }
  // The fluxes along x, y, z, cons_rhs and (MHD) ct along x, y, z.
  std::vector<std::vector<double>> fast, portable;
  CtFaceStorage ct;
  const CtFaces ct_views = ct.bind(b, g);
  for (int version = 0; version < 2; ++version) {
    use_portable_kernels(version == 1);
    if (mhd) {
      compute_block_fluxes_mhd(eos, RhsSettings{}, g, mg, ct_views, b, emfs);
      compute_block_rhs_mhd(g, mg.bvec, b);
      edge_emfs(emfs, mg, ct_views, b);
    } else {
      compute_block_fluxes(eos, RhsSettings{}, g, b);
      compute_block_rhs(g, b);
    }
    auto& out = version == 0 ? fast : portable;
    for (int d = 0; d < 3; ++d) out.push_back(copy(b, g.flux[d]));
    out.push_back(copy(b, g.cons_rhs));
    if (mhd) {
      for (int d = 0; d < 3; ++d) out.emplace_back(ct.data(d), ct.data(d) + ct.size(d));
      for (int d = 0; d < 3; ++d) out.push_back(copy(b, mg.emf[d]));
    }
  }
  use_portable_kernels(false);
  for (std::size_t d = 0; d < fast.size(); ++d) {
    EXPECT_EQ(differing(fast[d], portable[d]), 0) << (d < 3 ? "flux along " : d == 3 ? "cons_rhs " : d < 7 ? "ct along " : "emf along ") << d;
    int finite_nonzero = 0;
    for (double v : portable[d]) finite_nonzero += std::isfinite(v) && v != 0.0;
    EXPECT_GT(finite_nonzero, d < 7 ? 12 * 12 * 12 * 4 : 12 * 12 * 12) << d;  // an EMF group has one component
  }
}

TEST(KernelIsa, Avx2SweepsAndRowsHaveThePortableBitsIdealGas) {
  eos::EosConfig c;
  c.type = "ideal_gas";
  c.gamma = 2.0;
  c.T_max = 1e6;
  expect_same_bits(eos::make_eos(c), 1e-3, 1.0, 1);
}

TEST(KernelIsa, Avx2SweepsAndRowsHaveThePortableBitsPolytrope) {
  eos::EosConfig c;
  c.type = "polytrope";  // K = 100, Gamma = 2
  expect_same_bits(eos::make_eos(c), 1e-3, 1.0, 2);
}

TEST(KernelIsa, Avx2SweepsAndRowsHaveThePortableBitsSFHo) {
  const std::string table = std::string(REMNANT_SHARED_EOS_DIR) + "/SFHo_reduced_39r_39t_20y.h5";
  if (!std::filesystem::exists(table)) GTEST_SKIP() << "no table " << table;
  eos::EosConfig c;
  c.type = "tabulated";
  c.table_file = table;
  expect_same_bits(eos::make_eos(c), 1e-3, 5.0, 3);
}

TEST(KernelIsa, Avx2MhdSweepsAndRowsHaveThePortableBits) {
  eos::EosConfig c;
  c.type = "ideal_gas";
  c.gamma = 2.0;
  c.T_max = 1e6;
  const eos::EOS ideal = eos::make_eos(c);
  expect_same_bits(ideal, 1e-3, 1.0, 4, true, EmfScheme::uct_hll);
  expect_same_bits(ideal, 1e-3, 1.0, 5, true, EmfScheme::arithmetic);
  c.type = "polytrope";
  expect_same_bits(eos::make_eos(c), 1e-3, 1.0, 6, true, EmfScheme::uct_hll);
}

}  // namespace
