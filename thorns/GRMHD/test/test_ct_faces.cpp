// The face data of the edge EMFs (src/ct_faces.hpp) are one block's scratch, not grid groups
// (issue 21, goal 7: 216 B per cell as groups ct_x/y/z): GRMHD declares no such group, its groups
// cost what the fluxes and EMFs need, and a CtFaceStorage bound to block after block keeps one
// block's data at the flux groups' offsets (which the sweeps write through), without reallocating.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <memory>

#include "ct_faces.hpp"
#include "kernel_block.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;

TEST(CtFaces, GrmhdDeclaresNoPerCellFaceDataOfTheEmfs) {
  const VariableRegistry vars = test::kernel_registry();
  for (const char* name : {"GRMHD::ct_x", "GRMHD::ct_y", "GRMHD::ct_z"})
    EXPECT_LT(vars.find(name), 0) << name << " is a grid group again: the EMFs' face data are per-block scratch";
  // A 16^3 block with 3 ghosts (the TOV runs' blocks): GRMHD's groups are the fluxes (6 components on
  // the faces of each direction with one ghost layer: 3 x 6 x 19 x 18 x 18 points) and the EMFs
  // (3 x 17 x 17 x 16 edges), 243.5 B/cell; with ct_x/y/z (6 components more per face) 459.9.
  constexpr int n = 16;
  const std::unique_ptr<Block> block = test::kernel_block(vars, n);
  double bytes = 0;
  for (const auto& spec : vars.groups())
    if (spec.thorn == "GRMHD") bytes += 8.0 * static_cast<double>(block->size(spec.id));
  const double per_cell = bytes / (n * n * n);
  const double fluxes = 3.0 * kNumCons * 19 * 18 * 18 * 8 / (n * n * n), emfs = 3.0 * 17 * 17 * 16 * 8 / (n * n * n);
  EXPECT_DOUBLE_EQ(per_cell, fluxes + emfs) << "GRMHD's groups: " << per_cell << " B/cell";
  EXPECT_LT(per_cell, 250.0);
}

TEST(CtFaces, OneStorageHoldsOneBlockAtTheFluxOffsetsAndIsReused) {
  const VariableRegistry vars = test::kernel_registry();
  const Groups g = test::hydro_groups(vars);
  constexpr int n = 8;
  const std::unique_ptr<Block> first = test::kernel_block(vars, n), second = test::kernel_block(vars, n);
  CtFaceStorage storage;
  const CtFaces a = storage.bind(*first, g);
  std::size_t one_block = 0;
  for (int d = 0; d < 3; ++d) one_block += kNumCt * first->points_per_component(g.flux[d]) * sizeof(double);
  EXPECT_EQ(storage.bytes(), one_block);
  for (int d = 0; d < 3; ++d) {
    const Field flux = first->field(g.flux[d], 0);
    EXPECT_EQ(storage.size(d), kNumCt * first->points_per_component(g.flux[d]));
    for (int q = 0; q < kNumCt; ++q) {
      const Field& f = a.f[d][q];
      EXPECT_EQ(f.sj, flux.sj);
      EXPECT_EQ(f.sk, flux.sk);
      // Every face of the flux group's index space (one ghost layer) lies in component q's part.
      const int lo = -1, hi = n + 1;
      EXPECT_EQ(&f(lo, lo, lo) - storage.data(d), static_cast<std::ptrdiff_t>(q * first->points_per_component(g.flux[d])) +
                                                       (&flux(lo, lo, lo) - first->data(g.flux[d])));
      const int top[3] = {d == 0 ? hi : hi - 1, d == 1 ? hi : hi - 1, d == 2 ? hi : hi - 1};
      EXPECT_EQ(&f(top[0], top[1], top[2]) - storage.data(d),
                static_cast<std::ptrdiff_t>((q + 1) * first->points_per_component(g.flux[d])) - 1);
    }
  }
  a.f[0][kVtLeft](2, 3, 4) = 1.5;
  // The next block of the same shape: the same storage (no allocation per block), as written.
  const CtFaces b = storage.bind(*second, g);
  EXPECT_EQ(b.f[0][kVtLeft].origin, a.f[0][kVtLeft].origin);
  EXPECT_EQ(b.f[0][kVtLeft](2, 3, 4), 1.5);
  EXPECT_EQ(storage.bytes(), one_block);
  // uct_contact's per-block storage: the two induction fluxes only, the other views left alone.
  CtFaceStorage induction;
  CtFaces c = b;
  induction.bind(*second, g, c, kFluxNext, kNumCt);
  EXPECT_EQ(induction.bytes(), one_block / kNumCt * 2);
  EXPECT_EQ(c.f[1][kAlphaPlus].origin, b.f[1][kAlphaPlus].origin);
  EXPECT_NE(c.f[1][kFluxPrev].origin, b.f[1][kFluxPrev].origin);
  EXPECT_EQ(c.f[1][kFluxNext].sj, b.f[1][kFluxNext].sj);
}

}  // namespace
