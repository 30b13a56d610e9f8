// The Cartesian uct_hll EMF rows and face_rhs of constrained_transport.cpp (written as selects and
// with the face areas' factors hoisted, so that they run faster) must give the bits of the pointwise
// formulas: HLL of vt B with reconstruct's MC slope (detail::mc_slope) and the branch for a zero
// width, and Block::face_area. Random face data on a 3D Cartesian block, with zero speeds (width 0)
// and sign changes of the face-field differences (zero MC slope) among them; compared bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <random>

#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"

#include "GRMHD/reconstruction.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "constrained_transport.hpp"
#include "kernel_block.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd;

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

double hll_product_reference(double ap, double am, double vl, double vh, double bl, double bh) {
  const double w = ap + am;
  if (!(w > 0)) return 0.5 * (vl * bl + vh * bh);
  return (ap * vl * bl + am * vh * bh - ap * am * (bh - bl)) / w;
}

// What the upwind EMF reads at the edge at id: the HLL speeds and transverse velocities of the two
// a-faces adjacent along b, and B^b at the six faces along a around the edge (line[m]: offset m - 3).
struct EdgeInputs {
  double ap, am, vl, vh;
  double line[6];
};
EdgeInputs edge_inputs(Block& blk, const CtFaces& faces, int bface_group, int a, int b, const int* id) {
  int lo[3] = {id[0], id[1], id[2]};
  --lo[b];
  auto ct = [&](int q, const int* at) { return faces.f[a][q](at[0], at[1], at[2]); };
  EdgeInputs e;
  e.ap = std::max(ct(kAlphaPlus, lo), ct(kAlphaPlus, id));
  e.am = std::max(ct(kAlphaMinus, lo), ct(kAlphaMinus, id));
  e.vl = 0.5 * (ct(kVtLeft, lo) + ct(kVtLeft, id));
  e.vh = 0.5 * (ct(kVtRight, lo) + ct(kVtRight, id));
  for (int m = 0; m < 6; ++m) {
    int at[3] = {id[0], id[1], id[2]};
    at[a] += m - 3;
    e.line[m] = blk.field(bface_group, 0)(at[0], at[1], at[2]);
  }
  return e;
}

// -/+ HLL_a(vt^a B^b) of the edge at id with the MC slopes written out.
double upwind_reference(Block& blk, const CtFaces& ct, int bface_group, int a, int b, const int* id) {
  const EdgeInputs e = edge_inputs(blk, ct, bface_group, a, b, id);
  const double* q = e.line + 1;  // offsets -2 .. 1
  const double bl = q[1] + 0.5 * detail::mc_slope(q[1] - q[0], q[2] - q[1]);
  const double bh = q[2] - 0.5 * detail::mc_slope(q[2] - q[1], q[3] - q[2]);
  return hll_product_reference(e.ap, e.am, e.vl, e.vh, bl, bh);
}

// The face-sweep outputs the EMFs read (every CT component) and the face fields, uniform in [-1, 1]
// from `seed` on every point of the block; the HLL speeds alpha^+- through `speed` (v -> alpha >= 0).
template <class Speed>
void fill_random_ct_inputs(Block& blk, const MhdGroups& g, CtFaceStorage& storage, std::uint64_t seed, Speed speed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int d = 0; d < 3; ++d) {
    const std::size_t np = storage.size(d) / kNumCt;
    double* ct = storage.data(d);
    for (int q = 0; q < kNumCt; ++q)
      for (std::size_t i = 0; i < np; ++i) {
        double v = u(rng);
        if (q == kAlphaPlus || q == kAlphaMinus) v = speed(v);
        ct[static_cast<std::size_t>(q) * np + i] = v;
      }
    double* bf = blk.data(g.bface[d]);
    for (std::size_t i = 0; i < blk.size(g.bface[d]); ++i) bf[i] = u(rng);
  }
}

TEST(CtKernels, CartesianUctHllAndFaceRhsHaveTheBitsOfThePointwiseFormulas) {
  const VariableRegistry vars = test::kernel_registry();
  const MhdGroups g = test::mhd_groups(vars);
  constexpr int n = 6;
  const std::unique_ptr<Block> block = test::kernel_block(vars, n);
  Block& blk = *block;
  CtFaceStorage storage;
  const CtFaces ct = storage.bind(blk, test::hydro_groups(vars));
  // Speeds below 0.3 set to zero: edges with a zero HLL width.
  fill_random_ct_inputs(blk, g, storage, 42, [](double v) { return std::abs(v) < 0.3 ? 0.0 : std::abs(v); });
  int zero_width = 0;
  edge_emfs(EmfScheme::uct_hll, g, ct, blk);
  face_rhs(g, blk);
  for (int c = 0; c < 3; ++c) {
    const int a = (c + 1) % 3, bb = (c + 2) % 3;
    const double* ffa = blk.face_factors(a);
    const double* ffb = blk.face_factors(bb);
    const double* vwc = blk.volume_weights(c);
    int id[3];
    for (id[2] = 0; id[2] < n + (c != 2); ++id[2])
      for (id[1] = 0; id[1] < n + (c != 1); ++id[1])
        for (id[0] = 0; id[0] < n + (c != 0); ++id[0]) {
          const double emf = -upwind_reference(blk, ct, g.bface[bb], a, bb, id) +
                             upwind_reference(blk, ct, g.bface[a], bb, a, id);
          const double expect = emf * ffa[id[a]] * ffb[id[bb]] * vwc[id[c]] / blk.dx[c];
          const double got = blk.field(g.emf[c], 0)(id[0], id[1], id[2]);
          EXPECT_TRUE(same_bits(got, expect)) << "E_" << c << " at " << id[0] << " " << id[1] << " " << id[2] << ": "
                                              << got << " vs " << expect;
          int lo[3] = {id[0], id[1], id[2]};
          --lo[a];
          zero_width += ct.f[a][kAlphaPlus](lo[0], lo[1], lo[2]) == 0.0 &&
                        ct.f[a][kAlphaPlus](id[0], id[1], id[2]) == 0.0 &&
                        ct.f[a][kAlphaMinus](lo[0], lo[1], lo[2]) == 0.0 &&
                        ct.f[a][kAlphaMinus](id[0], id[1], id[2]) == 0.0;
        }
  }
  EXPECT_GT(zero_width, 0) << "no edge with a zero HLL width";
  for (int a = 0; a < 3; ++a) {
    const int bb = (a + 1) % 3, c = (a + 2) % 3;
    const Field ec = blk.field(g.emf[c], 0), eb = blk.field(g.emf[bb], 0), r = blk.field(g.bface_rhs[a], 0);
    int id[3];
    for (id[2] = 0; id[2] < n + (a == 2); ++id[2])
      for (id[1] = 0; id[1] < n + (a == 1); ++id[1])
        for (id[0] = 0; id[0] < n + (a == 0); ++id[0]) {
          int up_b[3] = {id[0], id[1], id[2]}, up_c[3] = {id[0], id[1], id[2]};
          ++up_b[bb];
          ++up_c[c];
          double circulation = 0;
          circulation += (ec(up_b[0], up_b[1], up_b[2]) - ec(id[0], id[1], id[2])) * blk.dx[c];
          circulation -= (eb(up_c[0], up_c[1], up_c[2]) - eb(id[0], id[1], id[2])) * blk.dx[bb];
          const double area = blk.face_area(a, id[0], id[1], id[2]);
          const double expect = area > 0 ? -circulation / area : 0.0;
          EXPECT_TRUE(same_bits(r(id[0], id[1], id[2]), expect)) << "face " << a << " at " << id[0] << " " << id[1] << " " << id[2];
        }
  }
}

// The Cartesian rows are MC only: with another edge reconstruction the EMFs must be those of that
// reconstruction (after the merge of the fast rows with GRMHD::emf_reconstruction the rows were taken
// for every reconstruction, so ppm_ep's 3D runs silently used MC edges). Reference: the same
// upwind formula with the face values reconstructed by `reconstruct` along the edge.
double upwind_reference_with(Block& blk, const CtFaces& ct, int bface_group, int a, int b, const int* id,
                             Reconstruction r) {
  const EdgeInputs e = edge_inputs(blk, ct, bface_group, a, b, id);
  double left[1], right[1], scratch[ppm_scratch_size(0)];
  reconstruct(r, e.line + 3, left, right, 0, scratch);
  return hll_product_reference(e.ap, e.am, e.vl, e.vh, left[0], right[0]);
}

TEST(CtKernels, CartesianUctHllUsesTheChosenEdgeReconstruction) {
  const VariableRegistry vars = test::kernel_registry();
  const MhdGroups g = test::mhd_groups(vars);
  constexpr int n = 6;
  const std::unique_ptr<Block> block = test::kernel_block(vars, n);
  Block& blk = *block;
  CtFaceStorage storage;
  const CtFaces ct = storage.bind(blk, test::hydro_groups(vars));
  fill_random_ct_inputs(blk, g, storage, 7, [](double v) { return std::abs(v) + 0.1; });
  for (Reconstruction r : {Reconstruction::ppm_ep, Reconstruction::ppm, Reconstruction::minmod}) {
    edge_emfs(EmfScheme::uct_hll, g, ct, blk, r);
    double worst = 0, scale = 0;
    for (int c = 0; c < 3; ++c) {
      const int a = (c + 1) % 3, bb = (c + 2) % 3;
      int id[3];
      for (id[2] = 0; id[2] < n + (c != 2); ++id[2])
        for (id[1] = 0; id[1] < n + (c != 1); ++id[1])
          for (id[0] = 0; id[0] < n + (c != 0); ++id[0]) {
            const double emf = -upwind_reference_with(blk, ct, g.bface[bb], a, bb, id, r) +
                               upwind_reference_with(blk, ct, g.bface[a], bb, a, id, r);
            const double expect = emf * blk.face_factors(a)[id[a]] * blk.face_factors(bb)[id[bb]] *
                                  blk.volume_weights(c)[id[c]] / blk.dx[c];
            worst = std::max(worst, std::abs(blk.field(g.emf[c], 0)(id[0], id[1], id[2]) - expect));
            scale = std::max(scale, std::abs(expect));
          }
    }
    EXPECT_LE(worst, 1e-14 * scale) << "edge reconstruction " << int(r) << ": the EMFs are not those of that reconstruction";
  }
}

// HydroBase's cell_centred_field runs in rows (1/psi^6 once per cell, the face areas from the
// per-direction arrays, the weighted mean as a select) to vectorise: it must give the bits of the
// per-cell formula with Block::face_area, in Cartesian 3D, in 2D (an unused direction: its one
// face) and on cylindrical and spherical blocks with the axis and the origin (zero-area faces, the
// orthonormal factor).
double cell_centred_reference(Block& blk, const MhdGroups& g, int metric, int a, int i, int j, int k) {
  const double psi = blk.field(metric, Metric::idx::psi)(i, j, k);
  const double p2 = psi * psi, ipsi6 = 1.0 / (p2 * p2 * p2);
  const Field bf = blk.field(g.bface[a], 0);
  if (!direction_used(blk, a)) return bf(i, j, k) * ipsi6;
  int up[3] = {i, j, k};
  ++up[a];
  const double lo = bf(i, j, k), hi = bf(up[0], up[1], up[2]);
  const double am = blk.face_area(a, i, j, k), ap = blk.face_area(a, up[0], up[1], up[2]);
  const double w = am + ap;
  double mean = w > 0 ? (am * lo + ap * hi) / w : 0.5 * (lo + hi);
  if (blk.coordinates != CoordinateSystem::cartesian && a > 0) {
    const int id[3] = {i, j, k};
    const Point3 f = coords::metric_diagonal(blk.coordinates, cell_point(blk, i, j, k));
    mean *= hydrobase::orthonormal_factor(blk, a, id) / std::sqrt(f[a]);
  }
  return mean * ipsi6;
}

void expect_cell_centred_bits(Block& blk, const VariableRegistry& vars, std::uint64_t seed) {
  const MhdGroups g = test::mhd_groups(vars);
  const int metric = vars.find("Spacetime::metric");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int d = 0; d < 3; ++d)
    for (std::size_t i = 0; i < blk.size(g.bface[d]); ++i) blk.data(g.bface[d])[i] = u(rng);
  for (std::size_t i = 0; i < blk.size(metric); ++i) blk.data(metric)[i] = 1.2 + 0.3 * u(rng);
  hydrobase::cell_centred_field({g.bface, g.bvec, metric}, blk);
  int mismatches = 0;
  for (int a = 0; a < 3; ++a)
    for_interior(blk, [&](int i, int j, int k) {
      mismatches += !same_bits(blk.field(g.bvec, a)(i, j, k), cell_centred_reference(blk, g, metric, a, i, j, k));
    });
  EXPECT_EQ(mismatches, 0);
}

TEST(CtKernels, CellCentredFieldHasTheBitsOfThePointwiseFormula) {
  const VariableRegistry vars = test::kernel_registry();
  {
    const std::unique_ptr<Block> block = test::kernel_block(vars, 6);
    expect_cell_centred_bits(*block, vars, 11);
  }
  {
    Block flat(0, 0, {0, 0, 0}, {7, 5, 1}, {3, 3, 0}, {0.0, 0.0, 0.0}, {0.3, 0.25, 1.0}, vars);
    ASSERT_FALSE(direction_used(flat, 2));
    expect_cell_centred_bits(flat, vars, 12);
  }
  {
    const std::unique_ptr<Block> block = test::kernel_block(vars, 6, {0.3, 0.25, 0.2});
    block->set_geometry(CoordinateSystem::cylindrical, {0.0, -0.6, 0.0});
    ASSERT_EQ(block->face_area(0, 0, 1, 1), 0.0);  // the axis
    expect_cell_centred_bits(*block, vars, 13);
  }
  {
    const std::unique_ptr<Block> block = test::kernel_block(vars, 6, {0.3, 0.25, 0.2});
    block->set_geometry(CoordinateSystem::spherical, {0.0, 0.0, 0.0});
    ASSERT_EQ(block->face_area(0, 0, 1, 1), 0.0);  // the origin
    expect_cell_centred_bits(*block, vars, 14);
  }
}

}  // namespace
