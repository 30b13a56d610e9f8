// Face fields of the problems on standalone Cartesian blocks: the discrete divergence is zero to
// round-off, the face values approximate the analytic field, the problems' energies converge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "diagnostics.hpp"
#include "face_fields.hpp"
#include "problems.hpp"

using namespace remnant;
using namespace remnant::mhd_tests;

namespace {

struct FaceBlock {
  VariableRegistry vars;
  std::unique_ptr<Block> block;
  Field bx, by, bz;
  // n cells per used direction on [lo, hi] (dim directions used), 2 ghosts.
  FaceBlock(int dim, std::array<int, 3> n, std::array<double, 3> lo, std::array<double, 3> hi) {
    const Centering c[3] = {Centering::face_x, Centering::face_y, Centering::face_z};
    for (int d = 0; d < 3; ++d) {
      VariableGroupSpec s;
      s.thorn = "Test";
      s.name = "B" + std::to_string(d + 1);
      s.centering = c[d];
      s.components = expand_tensor(TensorKind::scalar, s.name);
      vars.add(s);
    }
    std::array<int, 3> ng{0, 0, 0};
    std::array<double, 3> dx{};
    for (int d = 0; d < 3; ++d) {
      if (d >= dim) n[d] = 1;
      ng[d] = d < dim ? 2 : 0;
      dx[d] = (hi[d] - lo[d]) / n[d];
    }
    block = std::make_unique<Block>(0, 0, std::array<std::int64_t, 3>{0, 0, 0}, n, ng, lo, dx, vars);
    block->set_geometry(CoordinateSystem::cartesian, lo);
    bx = block->field(0, 0);
    by = block->field(1, 0);
    bz = block->field(2, 0);
  }
  // max |div B| dx_min / max |B| over the interior.
  double relative_divergence() const {
    const Block& b = *block;
    double worst = 0, bmax = 0, dx = 1e300;
    for (int d = 0; d < 3; ++d)
      if (b.n[d] > 1) dx = std::min(dx, b.dx[d]);
    for (int k = 0; k < b.n[2]; ++k)
      for (int j = 0; j < b.n[1]; ++j)
        for (int i = 0; i < b.n[0]; ++i) {
          worst = std::max(worst, std::abs(cell_divergence(b, bx, by, bz, i, j, k)));
          bmax = std::max({bmax, std::abs(bx(i, j, k)), std::abs(by(i, j, k)), std::abs(bz(i, j, k))});
        }
    return bmax > 0 ? worst * dx / bmax : 0;
  }
  // Integral of |B|^2 / 2 of the face means over the interior (2D).
  double energy() const {
    const Block& b = *block;
    double e = 0;
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) {
        const double x = 0.5 * (bx(i, j, 0) + bx(i + 1, j, 0)), y = 0.5 * (by(i, j, 0) + by(i, j + 1, 0));
        e += 0.5 * (x * x + y * y) * b.cell_volume(i, j, 0);
      }
    return e;
  }
};

}  // namespace

TEST(MHDTestsFaceFields, FieldLoopIsDivergenceFreeAndMatchesTheCurl) {
  for (auto profile : {FieldLoopParams::Profile::beckwith_stone, FieldLoopParams::Profile::smooth}) {
    FieldLoopParams p;
    p.profile = profile;
    p.centre = {0.8, 0.3};  // straddles the periodic boundaries: images must be used
    FaceBlock f(2, {128, 64, 1}, {-1, -0.5, -0.5}, {1, 0.5, 0.5});
    faces_from_potential(*f.block, [&](double x, double y) { return field_loop_potential(p, x, y); }, f.bx, f.by, f.bz);
    const double div = f.relative_divergence();
    std::printf("field loop (%s): max |div B| dx / max |B| = %.2e\n",
                profile == FieldLoopParams::Profile::smooth ? "smooth" : "Beckwith & Stone", div);
    EXPECT_LE(div, 1e-13);
    // Orientation: B = (dA/dy, -dA/dx) circulates counter-clockwise for A peaked at the centre:
    // below the centre B^x > 0, right of it B^y > 0.
    const Block& b = *f.block;
    const int ic = static_cast<int>((p.centre[0] + 1) / b.dx[0]), jc = static_cast<int>((p.centre[1] + 0.5) / b.dx[1]);
    EXPECT_GT(f.bx(ic, jc - 8, 0), 0.0) << "B^x below the centre (A increases upwards there)";
    EXPECT_LT(f.bx(ic, jc + 8, 0), 0.0) << "B^x above the centre";
    EXPECT_GT(f.by(ic + 8, jc, 0), 0.0) << "B^y right of the centre";
    // The face value is the face average of the analytic field: |B| = A0 inside the B&S loop.
    if (profile == FieldLoopParams::Profile::beckwith_stone) EXPECT_NEAR(f.bx(ic, jc - 8, 0), 1e-3, 2e-5);
  }
}

TEST(MHDTestsFaceFields, SmoothLoopEnergyConvergesAtSecondOrder) {
  FieldLoopParams p;
  p.profile = FieldLoopParams::Profile::smooth;
  const double exact = field_loop_magnetic_energy(p);
  double err[3];
  for (int s = 0; s < 3; ++s) {
    const int n = 32 << s;
    FaceBlock f(2, {2 * n, n, 1}, {-1, -0.5, -0.5}, {1, 0.5, 0.5});
    faces_from_potential(*f.block, [&](double x, double y) { return field_loop_potential(p, x, y); }, f.bx, f.by, f.bz);
    err[s] = std::abs(f.energy() - exact) / exact;
  }
  const double order = std::log2(err[1] / err[2]);
  std::printf("smooth loop initial energy errors %.3e %.3e %.3e, order %.2f\n", err[0], err[1], err[2], order);
  EXPECT_GT(order, 1.8);
}

TEST(MHDTestsFaceFields, UniformFieldFromItsPotentialIsExact) {
  FaceBlock f(2, {24, 24, 1}, {-6, -6, -0.5}, {6, 6, 0.5});
  faces_from_potential(*f.block, [](double x, double y) { return uniform_x_field_potential(1.0, x, y); }, f.bx, f.by, f.bz);
  const Block& b = *f.block;
  for (int j = 0; j < b.n[1]; ++j)
    for (int i = 0; i <= b.n[0]; ++i) EXPECT_NEAR(f.bx(i, j, 0), 1.0, 1e-14);
  for (int j = 0; j <= b.n[1]; ++j)
    for (int i = 0; i < b.n[0]; ++i) EXPECT_EQ(f.by(i, j, 0), 0.0);
  EXPECT_LE(f.relative_divergence(), 1e-14);
}

TEST(MHDTestsFaceFields, PotentialFieldIn3DHasZeroDivergence) {
  FieldLoopParams p;
  FaceBlock f(3, {16, 16, 8}, {-0.5, -0.5, -0.25}, {0.5, 0.5, 0.25});
  faces_from_potential(*f.block, [&](double x, double y) { return field_loop_potential(p, x, y); }, f.bx, f.by, f.bz);
  EXPECT_LE(f.relative_divergence(), 1e-13);
}

TEST(MHDTestsFaceFields, PlanarRiemannFieldIn1DAnd2D) {
  const RiemannProblem rp = riemann_problem(Problem::balsara5);
  auto transverse = [&](double x) {
    const FluidState& s = x < 0 ? rp.left : rp.right;
    return std::array<double, 2>{s.B[1], s.B[2]};
  };
  for (int dim : {1, 2}) {
    FaceBlock f(dim, {40, 8, 1}, {-0.5, -0.1, -0.5}, {0.5, 0.1, 0.5});
    faces_from_planar_field(*f.block, 2.0, transverse, f.bx, f.by, f.bz);
    const Block& b = *f.block;
    for (int j = 0; j < b.n[1]; ++j) {
      EXPECT_EQ(f.bx(0, j, 0), 2.0);
      EXPECT_EQ(f.bx(b.n[0], j, 0), 2.0);
      EXPECT_EQ(f.by(0, j, 0), 0.3);            // left state
      EXPECT_EQ(f.by(b.n[0] - 1, j, 0), -0.7);  // right state
      EXPECT_EQ(f.bz(0, j, 0), 0.3);
      EXPECT_EQ(f.bz(b.n[0] - 1, j, 0), 0.5);
    }
    if (dim == 2) EXPECT_EQ(f.by(b.n[0] - 1, b.n[1], 0), -0.7) << "upper y faces of a 2D block";
    EXPECT_EQ(f.relative_divergence(), 0.0) << dim << "D";
  }
}

// The per-cell diagnostics: round-off for potential fields, O(1) for a face that breaks the
// divergence (so the TSV maximum detects it), and b2 integrating to the loop's energy.
TEST(MHDTestsFaceFields, DiagnosticsSeeABrokenFace) {
  FieldLoopParams p;
  p.profile = FieldLoopParams::Profile::smooth;
  FaceBlock f(2, {128, 64, 1}, {-1, -0.5, -0.5}, {1, 0.5, 0.5});
  faces_from_potential(*f.block, [&](double x, double y) { return field_loop_potential(p, x, y); }, f.bx, f.by, f.bz);
  // Two cell groups on a second block sharing the geometry: reuse the face registry's block layout.
  VariableRegistry cells;
  for (const char* n : {"divB", "b2", "absB"}) {
    VariableGroupSpec s;
    s.thorn = "Test";
    s.name = n;
    s.components = expand_tensor(TensorKind::scalar, n);
    cells.add(s);
  }
  const Block& b = *f.block;
  Block out(0, 0, {0, 0, 0}, b.n, b.ng, b.lo, b.dx, cells);
  out.set_geometry(CoordinateSystem::cartesian, b.lo);
  const Field div = out.field(0, 0), b2 = out.field(1, 0), abs_b = out.field(2, 0);
  auto max_div = [&] {
    double m = 0;
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) m = std::max(m, div(i, j, 0));
    return m;
  };
  const double b_ref = max_face_value(*f.block, f.bx, f.by, f.bz);
  cell_diagnostics(*f.block, f.bx, f.by, f.bz, b_ref, 0.5, div, b2, abs_b);
  int zeroed = 0, kept = 0;
  for (int j = 0; j < b.n[1]; ++j)
    for (int i = 0; i < b.n[0]; ++i) {
      const double m = std::sqrt(2 * b2(i, j, 0));
      if (m < 0.5 * b_ref) {
        EXPECT_EQ(abs_b(i, j, 0), 0.0);
        zeroed += m > 0;
      } else {
        EXPECT_EQ(abs_b(i, j, 0), m);
        ++kept;
      }
    }
  EXPECT_GT(zeroed, 0);
  EXPECT_GT(kept, 0);
  const double clean = max_div();
  double energy = 0;
  for (int j = 0; j < b.n[1]; ++j)
    for (int i = 0; i < b.n[0]; ++i) energy += b2(i, j, 0) * b.cell_volume(i, j, 0);
  EXPECT_LE(clean, 1e-13);
  EXPECT_NEAR(energy / field_loop_magnetic_energy(p), 1.0, 1e-2);  // 6.5e-3 at 128 x 64
  f.bx(64, 32, 0) *= 1.01;  // a 1 % error on one face of the loop
  cell_diagnostics(*f.block, f.bx, f.by, f.bz, b_ref, 0.5, div, b2, abs_b);
  std::printf("divB diagnostic: clean %.2e, one face off by 1 %%: %.2e\n", clean, max_div());
  EXPECT_GT(max_div(), 1e-4);
}
