// Face-normal vectors (staggered B): a random divergence-free field (the discrete curl of a random
// edge potential) keeps a round-off divergence through divergence-preserving prolongation into
// new fine blocks, a second refinement and area-weighted restriction back, in Cartesian,
// cylindrical and spherical coordinates, 2D and 3D; restriction undoes prolongation; bad
// declarations are refused.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <tuple>

#include "remnant/error.hpp"
#include "stagger_test_util.hpp"

namespace remnant::grid::test {
namespace {

// The leaves of `grid` with every block of lowest radial index on `level` refined once.
std::vector<BlockKey> refine_inner_slab(const std::vector<BlockKey>& leaves, int level, int dim) {
  std::vector<BlockKey> out;
  for (const BlockKey& k : leaves) {
    if (k.level != level || k.index[0] != 0) {
      out.push_back(k);
      continue;
    }
    const int cz = dim >= 3 ? 2 : 1;
    for (int c2 = 0; c2 < cz; ++c2)
      for (int c1 = 0; c1 < 2; ++c1)
        for (int c0 = 0; c0 < 2; ++c0)
          out.push_back({level + 1, {2 * k.index[0] + c0, 2 * k.index[1] + c1, dim >= 3 ? 2 * k.index[2] + c2 : 0}});
  }
  return out;
}

std::vector<double> interior_faces(AmrGrid& grid, const FaceField& f) {
  std::vector<double> v;
  for (Block* b : grid.local_blocks())
    for (int d = 0; d < grid.dimension(); ++d) {
      const Field B = b->field(f.group[d], 0);
      for (int k = 0; k < b->n[2] + (d == 2); ++k)
        for (int j = 0; j < b->n[1] + (d == 1); ++j)
          for (int i = 0; i < b->n[0] + (d == 0); ++i) v.push_back(b->face_area(d, i, j, k) > 0 ? B(i, j, k) : 0.0);
    }
  return v;
}

class StaggeredRegrid : public ::testing::TestWithParam<std::tuple<CoordinateSystem, int>> {};

TEST_P(StaggeredRegrid, DivergenceStaysAtRoundOff) {
  const auto [coords, dim] = GetParam();
  const FaceField f = make_face_field();
  AmrGrid grid(stagger_config(coords, dim), f.vars, MPI_COMM_SELF);
  fill_curl_of_random_potential(grid, f, 2, 12345);
  const DivergenceStats initial = divergence_stats(grid, f);
  EXPECT_LT(initial.relative, 1e-14);
  const std::vector<double> original = interior_faces(grid, f);
  const auto base = grid.all_blocks();
  // Prolongation into new level-1 blocks, then into level 2 from the prolonged data.
  const auto level1 = refine_inner_slab(base, 0, dim);
  ASSERT_TRUE(grid.set_leaves(level1));
  DivergenceStats s = divergence_stats(grid, f);
  EXPECT_LE(s.scaled, 1e-13) << "after prolongation to level 1";
  EXPECT_LE(s.relative, 1e-13) << "after prolongation to level 1";
  ASSERT_TRUE(grid.set_leaves(refine_inner_slab(level1, 1, dim)));
  EXPECT_EQ(grid.finest_level(), 2);
  s = divergence_stats(grid, f);
  EXPECT_LE(s.scaled, 1e-13) << "after prolongation to level 2";
  EXPECT_LE(s.relative, 1e-13) << "after prolongation to level 2";
  // Area-weighted restriction back, one level at a time.
  ASSERT_TRUE(grid.set_leaves(level1));
  s = divergence_stats(grid, f);
  EXPECT_LE(s.scaled, 1e-13) << "after restriction to level 1";
  ASSERT_TRUE(grid.set_leaves(base));
  s = divergence_stats(grid, f);
  EXPECT_LE(s.scaled, 1e-13) << "after restriction to level 0";
  EXPECT_LE(s.relative, 1e-13) << "after restriction to level 0";
  // The fine fluxes of each coarse face sum to the coarse flux: restriction undoes prolongation.
  const std::vector<double> back = interior_faces(grid, f);
  ASSERT_EQ(back.size(), original.size());
  double worst = 0, scale = 0;
  for (std::size_t p = 0; p < back.size(); ++p) {
    worst = std::max(worst, std::abs(back[p] - original[p]));
    scale = std::max(scale, std::abs(original[p]));
  }
  EXPECT_LT(worst, 1e-13 * scale);
}

// A refined region that grows next to fine blocks the old mesh had: the new blocks take the kept
// blocks' copies of the shared faces (the fine data differ from what prolongation would give),
// and every cell keeps a round-off divergence.
TEST_P(StaggeredRegrid, GrowingRegionTakesTheKeptFineFaces) {
  const auto [coords, dim] = GetParam();
  const FaceField f = make_face_field();
  AmrGrid grid(stagger_config(coords, dim), f.vars, MPI_COMM_SELF);
  const auto base = grid.all_blocks();
  ASSERT_TRUE(grid.set_leaves(refine_inner_slab(base, 0, dim)));
  // Fine data of their own (a random potential resolved on level 1), consistent across levels.
  fill_curl_of_random_potential(grid, f, 1, 4242);
  EXPECT_EQ(shared_face_mismatch(grid, f), 0.0);
  // Refine the next slab of level-0 blocks: new level-1 blocks beside kept ones.
  std::vector<BlockKey> grown;
  for (const BlockKey& k : grid.all_blocks()) {
    if (k.level != 0 || k.index[0] != 1) {
      grown.push_back(k);
      continue;
    }
    const int cz = dim >= 3 ? 2 : 1;
    for (int c2 = 0; c2 < cz; ++c2)
      for (int c1 = 0; c1 < 2; ++c1)
        for (int c0 = 0; c0 < 2; ++c0)
          grown.push_back({1, {2 * k.index[0] + c0, 2 * k.index[1] + c1, dim >= 3 ? 2 * k.index[2] + c2 : 0}});
  }
  ASSERT_TRUE(grid.set_leaves(grown));
  EXPECT_EQ(shared_face_mismatch(grid, f), 0.0);
  const DivergenceStats s = divergence_stats(grid, f);
  EXPECT_LE(s.scaled, 1e-13);
  EXPECT_LE(s.relative, 1e-13);
}

INSTANTIATE_TEST_SUITE_P(Coordinates, StaggeredRegrid,
                         ::testing::Combine(::testing::Values(CoordinateSystem::cartesian, CoordinateSystem::cylindrical,
                                                              CoordinateSystem::spherical),
                                            ::testing::Values(2, 3)),
                         [](const auto& info) {
                           return std::string(to_string(std::get<0>(info.param))) + "_" +
                                  std::to_string(std::get<1>(info.param)) + "D";
                         });

// A linear divergence-free field is prolonged exactly away from the domain faces (where outflow
// ghosts limit the slopes): the prolongation is second order, not merely divergence-free (the
// old face prolongation, constant across a face, also kept a Cartesian divergence but not this).
TEST(StaggeredProlongation, LinearFieldIsExactInCartesian3D) {
  const FaceField f = make_face_field();
  AmrGrid grid(stagger_config(CoordinateSystem::cartesian, 3), f.vars, MPI_COMM_SELF);
  auto field = [](int d, const Point3& x) {
    switch (d) {
      case 0: return 1.0 + 0.5 * x[0] + 0.3 * x[1] - 0.2 * x[2];
      case 1: return 2.0 + 0.4 * x[0] - 0.25 * x[1] + 0.1 * x[2];
      default: return -1.0 + 0.2 * x[0] + 0.7 * x[1] - 0.25 * x[2];
    }
  };
  auto face_centre = [](Block& b, int d, int i, int j, int k) {
    const int p[3] = {i, j, k};
    Point3 x{};
    for (int e = 0; e < 3; ++e)
      x[static_cast<std::size_t>(e)] = e == d ? b.face_coordinate(e, p[e]) : b.centroid(e, p[e]);
    return x;
  };
  for (Block* b : grid.local_blocks())
    for (int d = 0; d < 3; ++d) {
      const Field B = b->field(f.group[d], 0);
      for (int k = 0; k <= b->n[2]; ++k)
        for (int j = 0; j <= b->n[1]; ++j)
          for (int i = 0; i <= b->n[0]; ++i) B(i, j, k) = field(d, face_centre(*b, d, i, j, k));
    }
  ASSERT_TRUE(grid.set_leaves(refine_inner_slab(grid.all_blocks(), 0, 3)));
  const double margin = 1.0 - 2.5 * 2.0 / 16;
  double worst = 0;
  std::int64_t checked = 0;
  for (Block* b : grid.local_blocks()) {
    if (b->level == 0) continue;
    for (int d = 0; d < 3; ++d) {
      const Field B = b->field(f.group[d], 0);
      for (int k = 0; k < b->n[2] + (d == 2); ++k)
        for (int j = 0; j < b->n[1] + (d == 1); ++j)
          for (int i = 0; i < b->n[0] + (d == 0); ++i) {
            const Point3 x = face_centre(*b, d, i, j, k);
            if (std::abs(x[0]) > margin || std::abs(x[1]) > margin || std::abs(x[2]) > margin) continue;
            ++checked;
            worst = std::max(worst, std::abs(B(i, j, k) - field(d, x)));
          }
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_LT(worst, 1e-14);
}

// An evolved edge group (say a vector potential A_z on the z edges of a 3D nested Cartesian mesh):
// a field linear in the coordinates is exchanged exactly at one level and across levels up to its
// slope along the edges (prolongation is bilinear across, constant along), and a regrid that
// refines and coarsens back returns the original values.
TEST(StaggeredEdges, EvolvedEdgeGroupsExchangeAndRegrid) {
  GridConfig c = stagger_config(CoordinateSystem::cartesian, 3);
  c.ghost_zones = 3;
  c.ncells = {32, 32, 32};
  c.max_level = 1;
  c.regions = {{RegionKind::box, RegionMode::at_least, 1, {-0.4, 0.4, -0.4, 0.4, -0.4, 0.4}}};
  VariableRegistry vars;
  VariableGroupSpec g;
  g.thorn = "Test";
  g.name = "Az";
  g.centering = Centering::edge_z;
  g.components = expand_tensor(TensorKind::scalar, "Az");
  g.role = VariableRole::evolved;
  g.rhs = "Az_rhs";
  const int az = vars.add(std::move(g));
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  auto value = [](double x, double y, double z) { return 1 + 2 * x - y + 0.5 * z; };
  auto at = [](Block& b, int i, int j, int k) {
    return std::array<double, 3>{b.face_coordinate(0, i), b.face_coordinate(1, j), b.x(2, k)};
  };
  std::vector<double> original;
  for (Block* b : grid.local_blocks()) {
    Field f = b->field(az, 0);
    for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
      for (int j = -b->ng[1]; j <= b->n[1] + b->ng[1]; ++j)
        for (int i = -b->ng[0]; i <= b->n[0] + b->ng[0]; ++i) {
          const bool inside = i >= 0 && i <= b->n[0] && j >= 0 && j <= b->n[1] && k >= 0 && k < b->n[2];
          const auto x = at(*b, i, j, k);
          f(i, j, k) = inside ? value(x[0], x[1], x[2]) : std::nan("");
          if (inside) original.push_back(f(i, j, k));
        }
  }
  const std::vector<int> groups = {az};
  grid.synchronize(groups);
  std::int64_t wrong = 0, coarse_fine = 0;
  for (Block* b : grid.local_blocks()) {
    Field f = b->field(az, 0);
    for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
      for (int j = -b->ng[1]; j <= b->n[1] + b->ng[1]; ++j)
        for (int i = -b->ng[0]; i <= b->n[0] + b->ng[0]; ++i) {
          const auto x = at(*b, i, j, k);
          if (!(std::abs(x[0]) <= 1 && std::abs(x[1]) <= 1 && std::abs(x[2]) < 1)) continue;
          const bool ghost = i < 0 || i > b->n[0] || j < 0 || j > b->n[1] || k < 0 || k >= b->n[2];
          // From a coarser block: constant along z, off by the z slope times a quarter coarse cell.
          const double tol = ghost && b->level > 0 ? 0.5 * (2.0 / 32) / 4 + 1e-13 : 1e-13;
          if (ghost && b->level > 0 && std::abs(f(i, j, k) - value(x[0], x[1], x[2])) > 1e-13) ++coarse_fine;
          if (!(std::abs(f(i, j, k) - value(x[0], x[1], x[2])) <= tol) && ++wrong <= 5)
            ADD_FAILURE() << "level " << b->level << " edge (" << i << "," << j << "," << k << "): got " << f(i, j, k)
                          << ", want " << value(x[0], x[1], x[2]);
        }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(coarse_fine, 0);  // prolonged ghosts were checked
  const auto before = grid.all_blocks();
  ASSERT_TRUE(grid.set_leaves(refine_inner_slab(before, 0, 3)));
  ASSERT_TRUE(grid.set_leaves(before));
  std::size_t p = 0;
  double worst = 0;
  for (Block* b : grid.local_blocks()) {
    Field f = b->field(az, 0);
    for (int k = 0; k < b->n[2]; ++k)
      for (int j = 0; j <= b->n[1]; ++j)
        for (int i = 0; i <= b->n[0]; ++i) worst = std::max(worst, std::abs(f(i, j, k) - original[p++]));
  }
  EXPECT_LT(worst, 1e-14);
}

TEST(StaggeredDeclarations, IncompleteVectorOrEvolvedVerticesAreRefused) {
  auto expect_error = [](VariableRegistry& vars, const std::string& fragment) {
    try {
      AmrGrid grid(stagger_config(CoordinateSystem::cartesian, 2), vars, MPI_COMM_SELF);
      ADD_FAILURE() << "no error; expected one mentioning '" << fragment << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  auto group = [](const std::string& name, Centering c, VariableRole role, const std::string& prolongation) {
    VariableGroupSpec g;
    g.thorn = "T";
    g.name = name;
    g.centering = c;
    g.components = expand_tensor(TensorKind::scalar, name);
    g.role = role;
    g.prolongation = prolongation;
    g.where = {"T/thorn.yaml", 7, 3};
    return g;
  };
  {
    VariableRegistry vars;  // face_y partner missing
    vars.add(group("Bx", Centering::face_x, VariableRole::evolved, "divergence_preserving"));
    expect_error(vars, "none with centering face_y");
  }
  {
    VariableRegistry vars;
    vars.add(group("P", Centering::vertex, VariableRole::evolved, "conservative_linear"));
    expect_error(vars, "T/thorn.yaml:7:3: error: evolved group 'T::P' is vertex-centred");
  }
  {
    VariableRegistry vars;  // an evolved edge group (a vector potential) is fine
    vars.add(group("A", Centering::edge_z, VariableRole::evolved, "conservative_linear"));
    EXPECT_NO_THROW(AmrGrid(stagger_config(CoordinateSystem::cartesian, 2), vars, MPI_COMM_SELF));
  }
  {
    VariableRegistry vars;
    vars.add(group("F", Centering::face_x, VariableRole::evolved, "conservative_linear"));
    expect_error(vars, "needs 'prolongation: divergence_preserving'");
  }
  {
    VariableRegistry vars;
    vars.add(group("c", Centering::cell, VariableRole::evolved, "divergence_preserving"));
    expect_error(vars, "needs face_x, face_y or face_z");
  }
}

}  // namespace
}  // namespace remnant::grid::test
