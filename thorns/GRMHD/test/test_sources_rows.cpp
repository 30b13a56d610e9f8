// 3D Cartesian blocks take pass 2 (flux divergence + sources, rhs.cpp) in vectorised rows; every
// other block goes cell by cell. The rows must give the bits of the cell-by-cell path: random
// primitives, metric (with and without shift), fluxes and (MHD) cell-centred fields on a 3D
// Cartesian block, both paths, cons_rhs compared bit for bit.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "kernel_block.hpp"
#include "rhs.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;

void fill(Block& b, const Groups& g, int bvec, bool shift, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto component = [&](int group, int c, auto value) { test::fill_component(b, group, c, value); };
  for (int c = 0; c < Prim::ncomp; ++c) component(g.prim, c, [&] { return 0.1 + u(rng); });
  for (int c : {int{Prim::idx::vel}, int{Prim::idx::vel2}, int{Prim::idx::vel3}}) component(g.prim, c, [&] { return 0.6 * (u(rng) - 0.5); });
  component(g.prim, Prim::idx::W, [&] { return 1.0 + 0.3 * u(rng); });
  component(g.metric, Metric::idx::psi, [&] { return 1.0 + 0.2 * u(rng); });
  component(g.metric, Metric::idx::alpha, [&] { return 0.6 + 0.4 * u(rng); });
  for (int c : {int{Metric::idx::beta}, int{Metric::idx::beta2}, int{Metric::idx::beta3}})
    component(g.metric, c, [&] { return shift ? 0.2 * (u(rng) - 0.5) : 0.0; });
  for (int d = 0; d < 3; ++d)
    for (int c = 0; c < kNumCons; ++c) component(g.flux[d], c, [&] { return u(rng) - 0.5; });
  if (bvec >= 0)
    for (int c = 0; c < 3; ++c) component(bvec, c, [&] { return u(rng) - 0.5; });
}

void expect_rows_match_cells(bool mhd, bool shift, std::uint64_t seed) {
  const VariableRegistry vars = test::kernel_registry();
  const Groups g = test::hydro_groups(vars);
  const int bvec = mhd ? test::mhd_groups(vars).bvec : -1;
  const std::unique_ptr<Block> block = test::kernel_block(vars, 8);
  Block& b = *block;
  fill(b, g, bvec, shift, seed);
  if (mhd) compute_block_rhs_mhd(g, bvec, b);
  else compute_block_rhs(g, b);
  const std::vector<double> rows(b.data(g.cons_rhs), b.data(g.cons_rhs) + b.size(g.cons_rhs));
  if (mhd) compute_block_rhs_mhd_per_cell(g, bvec, b);
  else compute_block_rhs_per_cell(g, b);
  const double* cells = b.data(g.cons_rhs);
  int differ = 0, nonzero = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    differ += std::bit_cast<std::uint64_t>(rows[i]) != std::bit_cast<std::uint64_t>(cells[i]);
    nonzero += cells[i] != 0.0;
  }
  EXPECT_EQ(differ, 0) << (mhd ? "MHD" : "hydro") << (shift ? " with" : " without") << " shift";
  EXPECT_GT(nonzero, 8 * 8 * 8 * kNumCons / 2);
}

TEST(SourcesRows, HydroRowsHaveTheBitsOfTheCellByCellPath) {
  expect_rows_match_cells(false, false, 1);
  expect_rows_match_cells(false, true, 2);
}

TEST(SourcesRows, MhdRowsHaveTheBitsOfTheCellByCellPath) {
  expect_rows_match_cells(true, false, 3);
  expect_rows_match_cells(true, true, 4);
}

}  // namespace
