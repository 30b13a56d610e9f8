// Composite (AMR) multigrid: manufactured solutions of the psi-type and alpha psi-type equations on
// grids with two refined levels around the bump, in every coordinate system and dimension, at three
// resolutions (the block structure scaled with the resolution, so the refined regions stay put):
// second-order convergence of the leaf-cell error and resolution-independent V-cycle factors. A
// refined level covering the whole domain must reproduce the uniform solve at its resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "XCFC/composite_multigrid.hpp"
#include "manufactured.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;
using Box = std::array<std::array<double, 2>, 3>;

// Level l + 1 patches: the children of every level-l block that meets the box and whose
// neighbours (corners included) all belong to level l, so the layout is 2:1 balanced.
CompositeLayout nested_layout(const GridShape& base, std::array<int, 3> patch_cells, const std::vector<Box>& boxes) {
  CompositeLayout lay;
  lay.base = base;
  lay.patch_cells = patch_cells;
  for (int d = base.dimension; d < 3; ++d) lay.patch_cells[d] = 1;
  // Level-l blocks as a set of block indices; level 0: all.
  std::vector<std::array<int, 3>> blocks;
  std::array<int, 3> nblk{1, 1, 1};
  for (int d = 0; d < base.dimension; ++d) nblk[d] = base.n[d] / lay.patch_cells[d];
  for (int k = 0; k < nblk[2]; ++k)
    for (int j = 0; j < nblk[1]; ++j)
      for (int i = 0; i < nblk[0]; ++i) blocks.push_back({i, j, k});
  for (std::size_t l = 0; l < boxes.size(); ++l) {
    auto has = [&](std::array<int, 3> b) {
      for (int d = 0; d < 3; ++d)
        if (b[d] < 0 || b[d] >= nblk[d]) return true;  // outside the domain: no constraint
      for (const auto& x : blocks)
        if (x == b) return true;
      return false;
    };
    const double scale = std::pow(0.5, static_cast<double>(l));
    std::vector<std::array<int, 3>> next;
    for (const auto& b : blocks) {
      bool meets = true, balanced = true;
      for (int d = 0; d < base.dimension; ++d) {
        const double width = base.dx[d] * scale * lay.patch_cells[d];
        const double a = base.lo[d] + b[d] * width, c = a + width;
        meets &= c > boxes[l][d][0] && a < boxes[l][d][1];
      }
      for (int oz = -1; oz <= 1; ++oz)
        for (int oy = -1; oy <= 1; ++oy)
          for (int ox = -1; ox <= 1; ++ox) {
            const std::array<int, 3> o{ox, oy, oz};
            std::array<int, 3> nbk = b;
            bool skip = false;
            for (int d = 0; d < 3; ++d) {
              if (d >= base.dimension && o[d] != 0) skip = true;
              nbk[d] += o[d];
            }
            if (!skip) balanced &= has(nbk);
          }
      if (!meets || !balanced) continue;
      for (int c = 0; c < (base.dimension > 2 ? 2 : 1); ++c)
        for (int bb = 0; bb < (base.dimension > 1 ? 2 : 1); ++bb)
          for (int a = 0; a < 2; ++a) next.push_back({2 * b[0] + a, 2 * b[1] + bb, 2 * b[2] + c});
    }
    if (next.empty()) break;
    for (int d = 0; d < base.dimension; ++d) nblk[d] *= 2;
    lay.patches.emplace_back();
    for (const auto& b : next)
      lay.patches.back().push_back({b[0] * lay.patch_cells[0], b[1] * lay.patch_cells[1], b[2] * lay.patch_cells[2]});
    blocks = next;
  }
  return lay;
}

struct RefinedCase {
  std::string name;
  GridShape base;
  std::array<int, 3> patch_cells;
  std::vector<Box> boxes;  // refined regions (coordinates of the grid)
  Bump bump;
};

std::vector<RefinedCase> refined_cases() {
  const double pi = 3.141592653589793;
  std::vector<RefinedCase> out;
  for (const Case& c : all_cases()) {
    RefinedCase s{c.name, c.shape, {8, 8, 4}, {}, c.bump};
    const GridShape& g = c.shape;
    Box b1{}, b2{};
    for (int d = 0; d < 3; ++d) {
      const double lo = g.lo[d], hi = g.lo[d] + g.n[d] * g.dx[d];
      b1[d] = {lo, lo + 0.5 * (hi - lo)};
      b2[d] = {lo, lo + 0.2 * (hi - lo)};
    }
    if (c.shape.coordinates == CoordinateSystem::cartesian && c.shape.dimension == 2) {
      b1[0] = {-1.5, 1.5}, b2[0] = {-0.5, 0.5};  // the bump sits in the middle of x
    }
    if (c.shape.coordinates == CoordinateSystem::spherical && c.shape.dimension == 2) {
      b1[1] = {0, pi / 2}, b2[1] = {0, pi / 2};  // refine in r over all theta
      s.patch_cells = {8, 4, 1};
    }
    if (c.shape.dimension == 3) s.patch_cells = {4, 4, 4};
    if (c.shape.dimension == 1) s.patch_cells = {8, 1, 1};
    s.boxes = {b1, b2};
    out.push_back(s);
  }
  return out;
}

struct Result {
  double error;
  SolveStats stats;
  int levels;
  std::size_t leaf_cells;
  CompositeField u;
};

// Fills coefficient and exact arrays of every patch.
template <class F>
void for_all(const CompositeMultigrid& mg, F&& f) {
  const int L = mg.layout().finest();
  for (int t = 0; t <= L; ++t) {
    const int np = t == 0 ? 1 : static_cast<int>(mg.layout().patches[static_cast<std::size_t>(t - 1)].size());
    for (int p = 0; p < np; ++p) {
      const GridShape s = mg.patch_shape(t, p);
      for_cells(s, [&](std::size_t q, int i, int j, int k) { f(t, p, q, s.point(i, j, k)); });
    }
  }
}
std::vector<double>& at(CompositeField& f, int t, int p) {
  return t == 0 ? f.base : f.patch[static_cast<std::size_t>(t - 1)][static_cast<std::size_t>(p)];
}

Result solve_composite(const CompositeLayout& lay, const Bump& bump_in, bool nonlinear, bool fmg) {
  CompositeMultigrid mg(lay);
  Bump bump = bump_in;
  if (!nonlinear) bump.amplitude = -0.3;
  const CoordinateSystem cs = lay.base.coordinates;
  CompositeEquation eq;
  eq.s0 = mg.field();
  if (nonlinear) eq.s1 = mg.field(), eq.s7 = mg.field();
  else eq.k = mg.field();
  CompositeField exact = mg.field();
  for_all(mg, [&](int t, int p, std::size_t q, const Point3& x) {
    const Point3 X = coords::to_cartesian(cs, x);
    const double u = bump(X), lap = bump.laplacian(X);
    const double w = std::exp(-0.3 * (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));
    at(exact, t, p)[q] = u;
    if (nonlinear) {
      const double s1 = -0.2 * w, s7 = -0.05 * w;
      at(eq.s1, t, p)[q] = s1, at(eq.s7, t, p)[q] = s7;
      at(eq.s0, t, p)[q] = lap - s1 / u - s7 / std::pow(u, 7);
    } else {
      const double k = 0.3 * w;
      at(eq.k, t, p)[q] = k;
      at(eq.s0, t, p)[q] = lap - k * u;
    }
  });
  eq.boundary.dirichlet = [&](const Point3& x) { return bump(coords::to_cartesian(cs, x)); };
  CompositeField u = mg.field(nonlinear ? 1.0 : 0.0);
  SolveSettings set;
  set.tolerance = 1e-10;
  set.max_cycles = 60;
  set.full_multigrid = fmg;
  if (const char* e = std::getenv("XCFC_SWEEPS")) set.pre_sweeps = set.post_sweeps = std::atoi(e);
  Result r{0, mg.solve(eq, u, set), lay.finest(), 0, {}};
  for_all(mg, [&](int t, int p, std::size_t q, const Point3&) {
    if (mg.covered(t, p, q)) return;
    ++r.leaf_cells;
    r.error = std::max(r.error, std::abs(at(u, t, p)[q] - at(exact, t, p)[q]));
  });
  r.u = u;
  return r;
}

void check(bool nonlinear) {
  for (const RefinedCase& c : refined_cases()) {
    Result r[3];
    for (int m = 0; m < 3; ++m) {
      const int f = 1 << m;
      std::array<int, 3> pc = c.patch_cells;
      for (int d = 0; d < c.base.dimension; ++d) pc[d] *= f;
      r[m] = solve_composite(nested_layout(scaled(c.base, f), pc, c.boxes), c.bump, nonlinear, m == 1);
    }
    const double p1 = order(r[0].error, r[1].error), p2 = order(r[1].error, r[2].error);
    std::printf("composite %-10s %-15s levels %d leaf cells %zu..%zu  Linf error %.3e %.3e %.3e  order %.2f %.2f  V-cycles %d %d %d  factor %.3f %.3f %.3f\n",
                nonlinear ? "psi-type" : "alpsi-type", c.name.c_str(), r[2].levels, r[0].leaf_cells, r[2].leaf_cells,
                r[0].error, r[1].error, r[2].error, p1, p2, r[0].stats.cycles, r[1].stats.cycles, r[2].stats.cycles,
                r[0].stats.factor, r[1].stats.factor, r[2].stats.factor);
    for (const auto& x : r) {
      EXPECT_TRUE(x.stats.converged) << c.name;
      EXPECT_EQ(x.levels, 2) << c.name;
    }
    EXPECT_GT(p2, 1.8) << c.name;
    for (const auto& x : r) EXPECT_LT(x.stats.factor, 0.35) << c.name;  // the same bound at every resolution
  }
}

TEST(XCFCComposite, NonlinearPsiTypeSecondOrder) { check(true); }
TEST(XCFCComposite, LinearAlphaPsiTypeSecondOrder) { check(false); }

// A refined level that covers the whole domain: the leaf solution is the uniform solution of the
// refined resolution (the coarse level only accelerates).
TEST(XCFCComposite, FullyRefinedLevelEqualsUniformSolve) {
  for (const RefinedCase& c : refined_cases()) {
    Box all{};
    for (int d = 0; d < 3; ++d) all[d] = {-1e9, 1e9};
    const CompositeLayout lay = nested_layout(c.base, c.patch_cells, {all});
    ASSERT_EQ(lay.finest(), 1) << c.name;
    const Result comp = solve_composite(lay, c.bump, true, false);
    // The same problem on the uniform grid of level 1.
    const GridShape fine = scaled(c.base, 2);
    Multigrid mg(fine);
    ScalarEquation eq;
    eq.s0.resize(fine.cells()), eq.s1.resize(fine.cells()), eq.s7.resize(fine.cells());
    std::vector<double> exact(fine.cells());
    for_cells(fine, [&](std::size_t q, int i, int j, int k) {
      const Point3 X = coords::to_cartesian(fine.coordinates, fine.point(i, j, k));
      const double u = c.bump(X), w = std::exp(-0.3 * (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));
      eq.s1[q] = -0.2 * w, eq.s7[q] = -0.05 * w;
      eq.s0[q] = c.bump.laplacian(X) - eq.s1[q] / u - eq.s7[q] / std::pow(u, 7);
      exact[q] = u;
    });
    eq.dirichlet = [&](const Point3& x) { return c.bump(coords::to_cartesian(fine.coordinates, x)); };
    std::vector<double> u(fine.cells(), 1.0);
    SolveSettings set;
    set.tolerance = 1e-10;
    ASSERT_TRUE(mg.solve(eq, u, set).converged);
    double err = 0, diff = 0;
    for (std::size_t q = 0; q < u.size(); ++q) err = std::max(err, std::abs(u[q] - exact[q]));
    for (std::size_t p = 0; p < lay.patches[0].size(); ++p) {
      const auto& corner = lay.patches[0][p];
      const GridShape ps = scaled(c.base, 1);
      for (int k = 0; k < (c.base.dimension > 2 ? lay.patch_cells[2] : 1); ++k)
        for (int j = 0; j < (c.base.dimension > 1 ? lay.patch_cells[1] : 1); ++j)
          for (int i = 0; i < lay.patch_cells[0]; ++i) {
            const std::size_t qp = static_cast<std::size_t>(i + lay.patch_cells[0] * (j + lay.patch_cells[1] * k));
            const std::size_t qu = static_cast<std::size_t>((corner[0] + i) + fine.n[0] * ((corner[1] + j) + fine.n[1] * (corner[2] + k)));
            diff = std::max(diff, std::abs(comp.u.patch[0][p][qp] - u[qu]));
          }
      (void)ps;
    }
    std::printf("fully refined %-15s composite error %.6e uniform error %.6e  max difference %.2e  V-cycles %d\n",
                c.name.c_str(), comp.error, err, diff, comp.stats.cycles);
    EXPECT_TRUE(comp.stats.converged) << c.name;
    EXPECT_LT(diff, 1e-8) << c.name;
  }
}

TEST(XCFCComposite, RejectsPatchesOutsideTheirParents) {
  CompositeLayout lay;
  lay.base = all_cases()[1].shape;  // cartesian 2D 32 x 16
  lay.patch_cells = {8, 8, 1};
  lay.patches = {{{0, 0, 0}}, {{40, 0, 0}}};  // level 2 patch far from the level 1 patch
  EXPECT_THROW(CompositeMultigrid mg(lay), std::invalid_argument);
  lay.patches = {{{4, 0, 0}}};  // not aligned
  EXPECT_THROW(CompositeMultigrid mg(lay), std::invalid_argument);
}

}  // namespace
