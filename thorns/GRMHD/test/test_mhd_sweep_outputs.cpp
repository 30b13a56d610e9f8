// With uct_hll the MHD sweep computes only what the uct_hll EMFs read (src/mhd_fluxes.hpp,
// MhdSweepOutputs): on the lines of the transverse ghost layers the speeds and transport velocities
// (ct components kAlphaPlus .. kVtRight), and the induction fluxes (kFluxNext, kFluxPrev) only on
// blocks with an unused direction. What it computes must keep the bits of the full sweep (that
// arithmetic and uct_contact take), what it skips must be left alone, and the EMFs must be the
// same. Random (non-smooth) states, every primitive and the metric random in every cell, ghosts
// too, on a 3D and a 2D Cartesian block.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "EOS/ideal_gas.hpp"
#include "constrained_transport.hpp"
#include "kernel_block.hpp"
#include "mhd_fluxes.hpp"
#include "remnant/cell_geometry.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

constexpr double kGamma = 2.0;

// A physical random state in every cell: rho, v (|v| < 0.5 in the CFC metric), p, eps, W, cs2 of the
// ideal gas; psi, alpha, beta; B^i and the face fields.
void fill_random_state(Block& b, const Groups& g, const MhdGroups& mg, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Field psi = b.field(g.metric, Metric::idx::psi), alpha = b.field(g.metric, Metric::idx::alpha);
  for (int k = -b.ng[2]; k < b.n[2] + b.ng[2]; ++k)
    for (int j = -b.ng[1]; j < b.n[1] + b.ng[1]; ++j)
      for (int i = -b.ng[0]; i < b.n[0] + b.ng[0]; ++i) {
        const double ps = 1.0 + 0.3 * u(rng), psi4 = ps * ps * ps * ps;
        psi(i, j, k) = ps;
        alpha(i, j, k) = 0.6 + 0.4 * u(rng);
        for (int c = 0; c < 3; ++c) b.field(g.metric, Metric::idx::beta + c)(i, j, k) = 0.1 * (u(rng) - 0.5);
        const double rho = 0.1 + u(rng), p = 0.05 + 0.5 * u(rng), eps = p / ((kGamma - 1.0) * rho);
        double v2 = 0;
        for (int c = 0; c < 3; ++c) {
          const double v = 0.5 * (u(rng) - 0.5) / std::sqrt(psi4);
          b.field(g.prim, Prim::idx::vel + c)(i, j, k) = v;
          v2 += psi4 * v * v;
        }
        b.field(g.prim, Prim::idx::rho)(i, j, k) = rho;
        b.field(g.prim, Prim::idx::press)(i, j, k) = p;
        b.field(g.prim, Prim::idx::eps)(i, j, k) = eps;
        b.field(g.prim, Prim::idx::temperature)(i, j, k) = 1.0;
        b.field(g.prim, Prim::idx::Ye)(i, j, k) = 0.1 + 0.3 * u(rng);
        b.field(g.prim, Prim::idx::W)(i, j, k) = 1.0 / std::sqrt(1.0 - v2);
        b.field(g.prim, Prim::idx::cs2)(i, j, k) = kGamma * p / (rho + kGamma / (kGamma - 1.0) * p);
        for (int c = 0; c < 3; ++c) b.field(mg.bvec, c)(i, j, k) = u(rng) - 0.5;
      }
  for (int d = 0; d < 3; ++d)
    for (std::size_t i = 0; i < b.size(mg.bface[d]); ++i) b.data(mg.bface[d])[i] = u(rng) - 0.5;
}

// The face data of one sweep: flux_x/y/z and the EMFs' face data (in `ct`), NaN before the sweep
// (what it leaves alone).
struct FaceData {
  std::vector<double> flux[3], ct[3];
};
FaceData sweep(Block& b, const Groups& g, const MhdGroups& mg, CtFaceStorage& ct, EmfScheme emfs) {
  const CtFaces views = ct.bind(b, g);
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  for (int d = 0; d < 3; ++d) {
    std::fill(b.data(g.flux[d]), b.data(g.flux[d]) + b.size(g.flux[d]), nan);
    std::fill(ct.data(d), ct.data(d) + ct.size(d), nan);
  }
  RhsSettings s;
  compute_block_fluxes_mhd(eos::EOS(eos::IdealGas(kGamma)), s, g, mg, views, b, emfs);
  FaceData out;
  for (int d = 0; d < 3; ++d) {
    out.flux[d].assign(b.data(g.flux[d]), b.data(g.flux[d]) + b.size(g.flux[d]));
    out.ct[d].assign(ct.data(d), ct.data(d) + ct.size(d));
  }
  return out;
}

// The full sweep's and the uct_hll sweep's face data and EMFs on block b (3D or 2D along z).
void expect_uct_hll_outputs(Block& b, const Groups& g, const MhdGroups& mg, std::uint64_t seed) {
  fill_random_state(b, g, mg, seed);
  const bool all_used = direction_used(b, 0) && direction_used(b, 1) && direction_used(b, 2);
  CtFaceStorage ct;
  const CtFaces views = ct.bind(b, g);
  const FaceData full = sweep(b, g, mg, ct, EmfScheme::arithmetic);
  const FaceData fast = sweep(b, g, mg, ct, EmfScheme::uct_hll);
  int differ = 0, ghost_speeds = 0, ghost_fluxes_left = 0, ghost_fluxes = 0, induction = 0, induction_left = 0;
  for (int d = 0; d < 3; ++d) {
    if (!direction_used(b, d)) continue;
    const Field f0 = b.field(g.flux[d], 0), c0 = views.f[d][0];
    const std::size_t nf = b.points_per_component(g.flux[d]), nc = nf;  // shaped as the flux groups
    int lo[3], hi[3];  // faces 0..n along d, one ghost layer in the used transverse directions
    for (int e = 0; e < 3; ++e) {
      lo[e] = e == d || !direction_used(b, e) ? 0 : -1;
      hi[e] = e == d ? b.n[e] : direction_used(b, e) ? b.n[e] : 0;
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          const int id[3] = {i, j, k};
          bool ghost = false;
          for (int e = 0; e < 3; ++e)
            if (e != d) ghost = ghost || id[e] < 0 || id[e] >= b.n[e];
          const std::size_t of = static_cast<std::size_t>(&f0(i, j, k) - b.data(g.flux[d]));
          const std::size_t oc = static_cast<std::size_t>(&c0(i, j, k) - ct.data(d));
          for (int q = 0; q < kNumCt; ++q) {
            const double want = full.ct[d][q * nc + oc], got = fast.ct[d][q * nc + oc];
            const bool speed = q <= kVtRight;
            if (speed || (!ghost && !all_used)) differ += !same_bits(want, got);
            if (speed && ghost) ghost_speeds += !std::isnan(got);
            if (!speed && !ghost) {
              induction += !std::isnan(want);
              induction_left += std::isnan(got);
            }
          }
          for (int q = 0; q < kNumCons; ++q) {
            const double want = full.flux[d][q * nf + of], got = fast.flux[d][q * nf + of];
            if (!ghost) {
              differ += !same_bits(want, got);
            } else {
              ghost_fluxes += !std::isnan(want);
              ghost_fluxes_left += std::isnan(got);
            }
          }
        }
  }
  EXPECT_EQ(differ, 0) << "face data that the uct_hll sweep must compute as the full one does";
  EXPECT_GT(ghost_speeds, 0);
  EXPECT_GT(ghost_fluxes, 0) << "the full sweep computes the ghost lines' fluxes";
  EXPECT_EQ(ghost_fluxes_left, ghost_fluxes) << "the uct_hll sweep solved HLL on ghost lines";
  EXPECT_GT(induction, 0);
  if (all_used) EXPECT_EQ(induction_left, induction) << "the uct_hll sweep computed induction fluxes in 3D";
  else EXPECT_EQ(induction_left, 0) << "the 1D fluxes of the edges with an unused direction";
  // The EMFs read only what both sweeps computed alike.
  std::vector<double> emf_full[3];
  sweep(b, g, mg, ct, EmfScheme::arithmetic);
  edge_emfs(EmfScheme::uct_hll, mg, views, b);
  for (int c = 0; c < 3; ++c) emf_full[c].assign(b.data(mg.emf[c]), b.data(mg.emf[c]) + b.size(mg.emf[c]));
  sweep(b, g, mg, ct, EmfScheme::uct_hll);
  edge_emfs(EmfScheme::uct_hll, mg, views, b);
  int emf_differ = 0, emf_nan = 0;
  for (int c = 0; c < 3; ++c)
    for (std::size_t i = 0; i < emf_full[c].size(); ++i) {
      emf_differ += !same_bits(emf_full[c][i], b.data(mg.emf[c])[i]);
      emf_nan += std::isnan(emf_full[c][i]);
    }
  EXPECT_EQ(emf_differ, 0);
  EXPECT_EQ(emf_nan, 0) << "an EMF read a face datum that no sweep computed";
}

TEST(MhdSweepOutputs, UctHllComputesOnlyWhatItsEmfsReadWithTheSameBits) {
  const VariableRegistry vars = test::kernel_registry();
  const Groups g = test::hydro_groups(vars);
  const MhdGroups mg = test::mhd_groups(vars);
  {
    const std::unique_ptr<Block> block = test::kernel_block(vars, 6);
    expect_uct_hll_outputs(*block, g, mg, 5);
  }
  {
    Block flat(0, 0, {0, 0, 0}, {7, 5, 1}, {3, 3, 0}, {0.0, 0.0, 0.0}, {0.3, 0.25, 1.0}, vars);
    expect_uct_hll_outputs(flat, g, mg, 6);
  }
}

}  // namespace
