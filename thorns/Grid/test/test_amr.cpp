// Mesh refinement: static regions and 2:1 balance, exact ghosts for linear data across
// coarse-fine boundaries (copy, restriction and prolongation agree with the centroids), regrids
// that conserve, and refluxing that makes the flux divergence telescope.
#include <gtest/gtest.h>

#include <map>
#include <mpi.h>

#include <cmath>
#include <numbers>

#include "forest.hpp"
#include "grid_test_util.hpp"

namespace remnant::grid::test {
namespace {

constexpr double kPi = std::numbers::pi;

GridConfig cartesian_nested(int dim) {
  GridConfig c;
  c.dimension = dim;
  c.ncells = {32, 32, 32};
  c.block_size = {8, 8, 8};
  c.ghost_zones = 3;
  c.max_level = 2;
  c.regions = {{RegionKind::box, RegionMode::at_least, 1, {-0.4, 0.4, -0.4, 0.4, -0.4, 0.4}},
               {RegionKind::box, RegionMode::at_least, 2, {-0.1, 0.2, -0.1, 0.1, -0.1, 0.1}}};
  return c;
}

GridConfig spherical_box(int dim) {
  GridConfig c;
  c.coordinates = CoordinateSystem::spherical;
  c.dimension = dim;
  c.ncells = {32, 32, 1};
  c.block_size = {8, 8, 1};
  c.ghost_zones = 3;
  c.xmin = {0, 0, 0};
  c.xmax = {2, kPi, 2 * kPi};
  c.boundary_lower = {Boundary::origin, Boundary::axis, Boundary::periodic};
  c.boundary_upper = {Boundary::outflow, Boundary::axis, Boundary::periodic};
  c.max_level = 1;
  c.regions = {{RegionKind::box, RegionMode::at_least, 1, {0.8, 1.2, 1.0, 1.6, 0, 0}}};
  return c;
}

double linear(const Point3& x) { return 1.0 + 0.5 * x[0] - 0.3 * x[1] + 0.2 * x[2]; }

// The leaves with the level-0 blocks at index[0] == 1, index[1] <= 1 (a 2D patch) replaced by their
// four children; `parents` counts the blocks refined.
std::vector<BlockKey> leaves_with_refined_patch(const AmrGrid& grid, int* parents = nullptr) {
  std::vector<BlockKey> leaves;
  for (const BlockKey& k : grid.all_blocks()) {
    if (k.index[0] == 1 && k.index[1] <= 1) {
      if (parents) ++*parents;
      for (int c1 = 0; c1 < 2; ++c1)
        for (int c0 = 0; c0 < 2; ++c0) leaves.push_back({1, {2 * k.index[0] + c0, 2 * k.index[1] + c1, 0}});
    } else {
      leaves.push_back(k);
    }
  }
  return leaves;
}

void fill(AmrGrid& grid, int g, double (*f)(const Point3&)) {
  for (Block* b : grid.local_blocks())
    for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
      for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
        for (int i = -b->ng[0]; i < b->n[0] + b->ng[0]; ++i) {
          const bool inside = i >= 0 && i < b->n[0] && j >= 0 && j < b->n[1] && k >= 0 && k < b->n[2];
          b->field(g, 0)(i, j, k) = inside ? f({b->centroid(0, i), b->centroid(1, j), b->centroid(2, k)}) : std::nan("");
        }
}

// Ghosts whose centroid lies inside the domain must hold the linear function exactly.
void expect_linear_ghosts(const GridConfig& c, int expected_levels) {
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  EXPECT_EQ(grid.finest_level() + 1, expected_levels) << grid.describe();
  fill(grid, u, linear);
  const std::vector<int> groups = {u};
  grid.synchronize(groups);
  std::int64_t wrong = 0, checked_points = 0, fine_coarse = 0;
  for (Block* b : grid.local_blocks())
    for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
      for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
        for (int i = -b->ng[0]; i < b->n[0] + b->ng[0]; ++i) {
          const Point3 x{b->centroid(0, i), b->centroid(1, j), b->centroid(2, k)};
          bool in_domain = true;
          for (int d = 0; d < c.dimension; ++d)
            in_domain &= x[static_cast<std::size_t>(d)] > c.xmin[static_cast<std::size_t>(d)] &&
                         x[static_cast<std::size_t>(d)] < c.xmax[static_cast<std::size_t>(d)];
          if (!in_domain) continue;
          ++checked_points;
          if (b->level > 0) ++fine_coarse;
          const double got = b->field(u, 0)(i, j, k), want = linear(x);
          if (!(std::abs(got - want) < 1e-13 * 4) && ++wrong <= 5)
            ADD_FAILURE() << "level " << b->level << " block (" << b->index[0] << "," << b->index[1] << ") point (" << i
                          << "," << j << "," << k << "): got " << got << ", want " << want;
        }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(fine_coarse, 0);
}

TEST(Amr, StaticBoxesMakeNestedLevels) {
  GridConfig c = cartesian_nested(2);
  VariableRegistry vars;
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  const auto per_level = grid.forest().blocks_per_level();
  ASSERT_EQ(per_level.size(), 3u) << grid.describe();
  EXPECT_GT(per_level[1], 0);
  EXPECT_GT(per_level[2], 0);
  // 2:1 balance: every neighbour of a leaf differs by at most one level (checked by the ghost plan,
  // which throws otherwise) and the leaves tile the domain.
  std::int64_t fine_cells = 0;
  for (const BlockKey& k : grid.all_blocks()) fine_cells += std::int64_t{1} << (2 * (2 - k.level));
  EXPECT_EQ(fine_cells, 16 * 16);
  EXPECT_NE(grid.describe().find("level 2"), std::string::npos);
}

TEST(Amr, LinearDataIsExactAcrossCoarseFineBoundaries) {
  expect_linear_ghosts(cartesian_nested(1), 3);
  expect_linear_ghosts(cartesian_nested(2), 3);
  expect_linear_ghosts(cartesian_nested(3), 3);
  expect_linear_ghosts(spherical_box(2), 2);
}

TEST(Amr, PaperSphericalLayoutHasOneCoarseCoreBlock) {
  // Level 2 in the shell 0.25 < r < 1, at most level 1 in r < 0.25 (one block of 8 cells of 1/32).
  GridConfig c = spherical_box(2);
  c.ncells = {32, 16, 1};
  c.xmax[1] = kPi / 2;
  c.boundary_upper[1] = Boundary::reflect;
  c.max_level = 2;
  c.regions = {{RegionKind::shell, RegionMode::at_least, 2, {0.25, 1.0, 0, 0, 0, 0}},
               {RegionKind::sphere, RegionMode::at_most, 1, {0, 0.25, 0, 0, 0, 0}}};
  VariableRegistry vars;
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  int core_blocks = 0;
  for (const BlockKey& k : grid.all_blocks())
    if (k.index[0] == 0) {
      EXPECT_EQ(k.level, 1) << "the core around the origin is on level 1";
      ++core_blocks;
    }
  EXPECT_EQ(core_blocks, 4) << "one block in r (8 cells of 1/32), four in theta at level 1";
  EXPECT_EQ(grid.finest_level(), 2);
}

TEST(Amr, RegridConservesAndRestrictionUndoesProlongation) {
  GridConfig c = spherical_box(2);
  c.regions.clear();
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  fill(grid, u, [](const Point3& x) { return 1 + std::exp(-8 * (x[0] - 1) * (x[0] - 1)) * std::cos(3 * x[1]); });
  const double before = grid.reduce(u, 0, ReductionKind::volume_integral);
  std::vector<double> original;
  for (Block* b : grid.local_blocks()) for_interior(*b, [&](int i, int j, int k) { original.push_back(b->field(u, 0)(i, j, k)); });
  // Refine a patch of blocks (with what balance requires), then everything back.
  const std::vector<BlockKey> refined = leaves_with_refined_patch(grid);
  const auto base = grid.all_blocks();
  ASSERT_TRUE(grid.set_leaves(refined));
  EXPECT_EQ(grid.finest_level(), 1);
  const double refined_total = grid.reduce(u, 0, ReductionKind::volume_integral);
  EXPECT_NEAR(refined_total / before, 1.0, 1e-14);
  ASSERT_TRUE(grid.set_leaves(base));
  EXPECT_NEAR(grid.reduce(u, 0, ReductionKind::volume_integral) / before, 1.0, 1e-14);
  std::size_t p = 0;
  double worst = 0;
  for (Block* b : grid.local_blocks())
    for_interior(*b, [&](int i, int j, int k) { worst = std::max(worst, std::abs(b->field(u, 0)(i, j, k) - original[p++])); });
  EXPECT_LT(worst, 1e-14);
}

// Memory (issue 21, goal 7): groups with fewer ghosts (thorn.yaml `ghosts`) regrid as before: one
// layer is all that prolongation reads, so a `ghosts: 1` group prolongs to the same bits as a group
// with the Grid's ghosts holding the same values, and a `ghosts: 0` group to those of one whose
// first ghost layer holds zeros (as the never-written ghosts of such groups did).
TEST(Amr, GroupsWithFewerGhostsRegrid) {
  GridConfig c = spherical_box(2);
  c.regions.clear();
  VariableRegistry vars;
  const int full = add_group(vars, "u", TensorKind::scalar);
  const int one = add_group(vars, "w", TensorKind::scalar);
  const int none = add_group(vars, "r", TensorKind::scalar);
  vars.group(full).role = vars.group(one).role = vars.group(none).role = VariableRole::auxiliary;
  vars.group(one).ghosts = 1;
  vars.group(one).prolongation = "linear";
  vars.group(none).ghosts = 0;
  vars.group(none).prolongation = "linear";
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  auto f = [](double x, double y) { return 1 + std::exp(-8 * (x - 1) * (x - 1)) * std::cos(3 * y); };
  for (Block* b : grid.local_blocks())
    for (int g : {full, one, none}) {
      const auto& ng = b->ghosts(g);
      for (int j = -ng[1]; j < b->n[1] + ng[1]; ++j)
        for (int i = -ng[0]; i < b->n[0] + ng[0]; ++i) {
          const bool inside = i >= 0 && i < b->n[0] && j >= 0 && j < b->n[1];
          const bool first_layer = i >= -1 && i <= b->n[0] && j >= -1 && j <= b->n[1];
          b->field(g, 0)(i, j, 0) = inside ? f(b->centroid(0, i), b->centroid(1, j)) : first_layer ? 0.0 : std::nan("");
        }
    }
  int parents = 0;
  const std::vector<BlockKey> refined = leaves_with_refined_patch(grid, &parents);
  const auto base = grid.all_blocks();
  ASSERT_TRUE(grid.set_leaves(refined));
  int children = 0;
  for (Block* b : grid.local_blocks()) {
    EXPECT_EQ(b->size(one), 10u * 10u);
    EXPECT_EQ(b->size(none), 8u * 8u);
    for_interior(*b, [&](int i, int j, int k) {
      ASSERT_EQ(b->field(one, 0)(i, j, k), b->field(full, 0)(i, j, k)) << "level " << b->level << " (" << i << "," << j << ")";
      ASSERT_EQ(b->field(none, 0)(i, j, k), b->field(full, 0)(i, j, k)) << "level " << b->level << " (" << i << "," << j << ")";
    });
    children += b->level == 1;
  }
  EXPECT_GT(parents, 0);
  EXPECT_EQ(children, 4 * parents);
  ASSERT_TRUE(grid.set_leaves(base));
  for (Block* b : grid.local_blocks())
    for_interior(*b, [&](int i, int j, int k) {
      ASSERT_EQ(b->field(one, 0)(i, j, k), b->field(full, 0)(i, j, k));
      ASSERT_EQ(b->field(none, 0)(i, j, k), b->field(full, 0)(i, j, k));
    });
}

// Memory (issue 21, goal 7): a regrid moves the blocks it keeps instead of copying them, so old and
// new storage coexist only for the blocks that change (a head-on run's peak RSS was 43 old + 64 new
// blocks at its initial regrid: 321 MB, then 276 MB). The kept blocks are the same objects, with
// their gids renumbered and their data untouched.
TEST(Amr, RegridMovesTheBlocksItKeeps) {
  GridConfig c = spherical_box(2);
  c.regions.clear();
  VariableRegistry vars;
  const int u = add_group(vars, "u", TensorKind::scalar);
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  fill(grid, u, [](const Point3& x) { return 1 + x[0] * std::cos(3 * x[1]); });
  std::map<std::pair<int, BlockIndex>, const Block*> before;
  for (Block* b : grid.local_blocks()) before[{b->level, b->index}] = b;
  const std::vector<BlockKey> refined = leaves_with_refined_patch(grid);
  ASSERT_TRUE(grid.set_leaves(refined));
  int kept = 0, fresh = 0;
  for (std::size_t i = 0; i < grid.local_blocks().size(); ++i) {
    const Block* b = grid.local_blocks()[i];
    EXPECT_EQ(b->gid, grid.local_blocks()[0]->gid + static_cast<std::int64_t>(i));
    const auto it = before.find({b->level, b->index});
    if (it == before.end()) {
      ++fresh;
      continue;
    }
    EXPECT_EQ(it->second, b) << "block (" << b->index[0] << "," << b->index[1] << ") was copied, not moved";
    ++kept;
  }
  EXPECT_GT(kept, 0);
  EXPECT_GT(fresh, 0);
}

// Flux densities that differ between levels; after correction the total of the divergences over
// a periodic domain vanishes (it telescopes), before it does not.
double divergence_total(AmrGrid& grid, int fx, int fy, bool correct) {
  for (Block* b : grid.local_blocks()) {
    for (int g : {fx, fy}) {
      const auto e = b->extent(grid.local_blocks()[0]->n[0] ? (g == fx ? Centering::face_x : Centering::face_y) : Centering::cell);
      (void)e;
      Field f = b->field(g, 0);
      const int d = g == fx ? 0 : 1;
      for (int j = 0; j < b->n[1] + (d == 1); ++j)
        for (int i = 0; i < b->n[0] + (d == 0); ++i) {
          const double x = d == 0 ? b->face_coordinate(0, i) : b->centroid(0, i);
          const double y = d == 1 ? b->face_coordinate(1, j) : b->centroid(1, j);
          f(i, j, 0) = std::sin(2 * kPi * x) * std::cos(2 * kPi * y) + 0.1 * b->level * (1 + x * y);
        }
    }
  }
  if (correct) {
    const std::vector<int> groups = {fx, fy};
    grid.correct_fluxes(groups);
  }
  double total = 0;
  for (Block* b : grid.local_blocks()) {
    Field f0 = b->field(fx, 0), f1 = b->field(fy, 0);
    for_interior(*b, [&](int i, int j, int k) {
      total += f0(i + 1, j, k) * b->face_area(0, i + 1, j, k) - f0(i, j, k) * b->face_area(0, i, j, k) +
               f1(i, j + 1, k) * b->face_area(1, i, j + 1, k) - f1(i, j, k) * b->face_area(1, i, j, k);
    });
  }
  return total;
}

TEST(Amr, RefluxingMakesTheDivergenceTelescope) {
  GridConfig c = cartesian_nested(2);
  c.boundary_lower = c.boundary_upper = {Boundary::periodic, Boundary::periodic, Boundary::periodic};
  c.regions.push_back({RegionKind::box, RegionMode::at_least, 1, {0.6, 1.0, -1.0, -0.6, 0, 0}});  // across the wrap
  VariableRegistry vars;
  const int fx = add_group(vars, "fx", TensorKind::scalar, Centering::face_x);
  const int fy = add_group(vars, "fy", TensorKind::scalar, Centering::face_y);
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  EXPECT_GT(std::abs(divergence_total(grid, fx, fy, false)), 1e-3);
  EXPECT_LT(std::abs(divergence_total(grid, fx, fy, true)), 1e-14);
}

TEST(Amr, FaceCentredGroupsExchangeAndRestrict) {
  // A face_x field linear in x and y is reproduced in every ghost face inside the domain.
  GridConfig c = cartesian_nested(2);
  VariableRegistry vars;
  const int fx = add_group(vars, "Bx", TensorKind::scalar, Centering::face_x);
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  auto value = [](double x, double y) { return 1 + 2 * x - y; };
  for (Block* b : grid.local_blocks()) {
    Field f = b->field(fx, 0);
    for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
      for (int i = -b->ng[0]; i <= b->n[0] + b->ng[0]; ++i) {
        const bool inside = i >= 0 && i <= b->n[0] && j >= 0 && j < b->n[1];
        f(i, j, 0) = inside ? value(b->face_coordinate(0, i), b->centroid(1, j)) : std::nan("");
      }
  }
  const std::vector<int> groups = {fx};
  grid.synchronize(groups);
  std::int64_t wrong = 0;
  for (Block* b : grid.local_blocks()) {
    Field f = b->field(fx, 0);
    for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
      for (int i = -b->ng[0]; i <= b->n[0] + b->ng[0]; ++i) {
        const double x = b->face_coordinate(0, i), y = b->centroid(1, j);
        if (!(x >= -1 && x <= 1 && y > -1 && y < 1)) continue;
        // Coarse-to-fine face prolongation is constant across the face (exact only in x): off by
        // the slope in y times a quarter of a coarse cell.
        const bool ghost = i < 0 || i > b->n[0] || j < 0 || j >= b->n[1];
        const double tol = ghost && b->level > 0 ? 1.0 * (2.0 / 32) / 4 + 1e-13 : 1e-13;
        if (!(std::abs(f(i, j, 0) - value(x, y)) <= tol) && ++wrong <= 5)
          ADD_FAILURE() << "level " << b->level << " face (" << i << "," << j << "): got " << f(i, j, 0) << ", want "
                        << value(x, y);
      }
  }
  EXPECT_EQ(wrong, 0);
}

TEST(Amr, LohnerRefinesASharpFeatureAndCoarsensWhenItIsGone) {
  GridConfig c;
  c.dimension = 2;
  c.ncells = {32, 32, 1};
  c.block_size = {8, 8, 1};
  c.max_level = 2;
  c.refine_variable = "Test::rho";
  c.refine_log = true;
  VariableRegistry vars;
  const int rho = add_group(vars, "rho", TensorKind::scalar);
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  auto set = [&](double width) {
    for (Block* b : grid.local_blocks())
      for_interior(*b, [&](int i, int j, int k) {
        const double r2 = b->x(0, i) * b->x(0, i) + b->x(1, j) * b->x(1, j);
        b->field(rho, 0)(i, j, k) = 1e-6 + std::exp(-r2 / (width * width));
      });
  };
  set(0.1);
  ASSERT_TRUE(grid.regrid());
  set(0.1);
  grid.regrid();
  EXPECT_EQ(grid.finest_level(), 2) << grid.describe();
  const auto refined_blocks = grid.all_blocks().size();
  for (int pass = 0; pass < 3; ++pass) {
    for (Block* b : grid.local_blocks()) for_interior(*b, [&](int i, int j, int k) { b->field(rho, 0)(i, j, k) = 1.0; });
    grid.regrid();
  }
  EXPECT_EQ(grid.finest_level(), 0) << "a flat density needs no refinement";
  EXPECT_LT(grid.all_blocks().size(), refined_blocks);
  EXPECT_EQ(grid.all_blocks().size(), 16u);
}

TEST(Amr, ThornCriteriaAndRegionCapsCombine) {
  GridConfig c;
  c.dimension = 2;
  c.ncells = {32, 32, 1};
  c.block_size = {8, 8, 1};
  c.max_level = 2;
  c.regions = {{RegionKind::box, RegionMode::at_most, 1, {0.0, 1.0, 0.0, 1.0, 0, 0}}};
  VariableRegistry vars;
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  grid.add_refinement_criterion("everywhere", [](Block&) { return 1; });
  grid.regrid();
  grid.regrid();
  for (const BlockKey& k : grid.all_blocks()) {
    const bool capped = k.index[0] >= (2 << k.level) && k.index[1] >= (2 << k.level);
    EXPECT_EQ(k.level, capped ? 1 : 2);
  }
  EXPECT_NE(grid.describe().find("criteria    everywhere"), std::string::npos) << grid.describe();
}

}  // namespace
}  // namespace remnant::grid::test
