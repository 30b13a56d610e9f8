// Block storage: extents per centering, component-major layout, origin at the first interior cell.
#include <gtest/gtest.h>

#include <string>

#include "grid_test_util.hpp"

namespace remnant::grid::test {
namespace {

TEST(Block, ExtentsPerCentering3D) {
  VariableRegistry vars;
  const int cell = add_group(vars, "u", TensorKind::vector);
  const int face = add_group(vars, "Bx", TensorKind::scalar, Centering::face_x);
  const int vertex = add_group(vars, "phi", TensorKind::scalar, Centering::vertex);
  Block b(7, 0, {1, 2, 3}, {8, 6, 4}, {2, 2, 2}, {0, 0, 0}, {0.1, 0.2, 0.3}, vars);
  EXPECT_EQ(b.extent(Centering::cell), (std::array<int, 3>{12, 10, 8}));
  EXPECT_EQ(b.extent(Centering::face_x), (std::array<int, 3>{13, 10, 8}));
  EXPECT_EQ(b.extent(Centering::edge_z), (std::array<int, 3>{13, 11, 8}));
  EXPECT_EQ(b.points_per_component(cell), 12u * 10u * 8u);
  EXPECT_EQ(b.size(cell), 3u * 12u * 10u * 8u);
  EXPECT_EQ(b.size(face), 13u * 10u * 8u);
  EXPECT_EQ(b.size(vertex), 13u * 11u * 9u);
  EXPECT_DOUBLE_EQ(b.cell_volume(), 0.1 * 0.2 * 0.3);
}

TEST(Block, UnusedDirectionsHaveNoGhostsAndNoStaggering) {
  VariableRegistry vars;
  add_group(vars, "phi", TensorKind::scalar, Centering::vertex);
  Block b(0, 0, {0, 0, 0}, {8, 4, 1}, {3, 3, 0}, {0, 0, 0}, {0.5, 0.25, 2.0}, vars);
  EXPECT_EQ(b.extent(Centering::vertex), (std::array<int, 3>{15, 11, 1}));
  EXPECT_DOUBLE_EQ(b.cell_volume(), 0.5 * 0.25);
}

TEST(Block, FieldIsComponentMajorWithOriginAtFirstInteriorCell) {
  VariableRegistry vars;
  const int g = add_group(vars, "v", TensorKind::vector);
  Block b(0, 0, {0, 0, 0}, {4, 3, 2}, {1, 1, 1}, {0, 0, 0}, {1, 1, 1}, vars);
  for (std::size_t p = 0; p < b.size(g); ++p) ASSERT_EQ(b.data(g)[p], 0.0) << "data starts at zero";
  const auto e = b.extent(Centering::cell);  // 6 x 5 x 4
  for (int c = 0; c < 3; ++c) {
    Field f = b.field(g, c);
    EXPECT_EQ(f.sj, e[0]);
    EXPECT_EQ(f.sk, e[0] * e[1]);
    const std::ptrdiff_t first_interior = 1 + 1 * e[0] + 1 * e[0] * e[1];
    EXPECT_EQ(&f(0, 0, 0), b.data(g) + c * b.points_per_component(g) + first_interior);
    EXPECT_EQ(&f(-1, -1, -1), b.data(g) + c * b.points_per_component(g));
    EXPECT_EQ(&f(1, 0, 0), &f(0, 0, 0) + 1) << "i is fastest";
  }
  EXPECT_THROW(b.field(g, 3), std::out_of_range);
}

// thorn.yaml `ghosts: N` (issue 21, memory): such a group is allocated with min(N, ng) ghost layers,
// its own strides and origin; the others keep the block's.
TEST(Block, GroupsDeclaringFewerGhostsAreAllocatedWithThem) {
  VariableRegistry vars;
  const int full = add_group(vars, "u", TensorKind::vector);
  const int none = add_group(vars, "rhs", TensorKind::vector);
  const int one = add_group(vars, "flux", TensorKind::scalar, Centering::face_x);
  const int edge = add_group(vars, "emf", TensorKind::scalar, Centering::edge_z);
  const int many = add_group(vars, "w", TensorKind::scalar);
  vars.group(none).ghosts = 0;
  vars.group(one).ghosts = 1;
  vars.group(edge).ghosts = 0;
  vars.group(many).ghosts = 8;  // more than the Grid's: the Grid's
  Block b(0, 0, {0, 0, 0}, {8, 6, 4}, {3, 3, 3}, {0, 0, 0}, {1, 1, 1}, vars);
  EXPECT_EQ(b.size(full), 3u * 14u * 12u * 10u);
  EXPECT_EQ(b.size(none), 3u * 8u * 6u * 4u) << "no ghosts: the interior only";
  EXPECT_EQ(b.size(one), 11u * 8u * 6u) << "one layer, plus the upper x face";
  EXPECT_EQ(b.size(edge), 9u * 7u * 4u);
  EXPECT_EQ(b.size(many), 14u * 12u * 10u);
  EXPECT_EQ(b.ghosts(none), (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(b.ghosts(one), (std::array<int, 3>{1, 1, 1}));
  EXPECT_EQ(b.group_extent(one), (std::array<int, 3>{11, 8, 6}));
  const Field r = b.field(none, 2);
  EXPECT_EQ(r.sj, 8);
  EXPECT_EQ(r.sk, 48);
  EXPECT_EQ(&r(0, 0, 0), b.data(none) + 2 * 8 * 6 * 4);
  EXPECT_EQ(&r(7, 5, 3), b.data(none) + b.size(none) - 1);
  const Field f = b.field(one, 0);
  EXPECT_EQ(&f(-1, -1, -1), b.data(one));
  EXPECT_EQ(&f(9, 6, 4), b.data(one) + b.size(one) - 1);
}

// 2D: unused directions have no ghosts and no staggering for such groups either.
TEST(Block, FewerGhostsIn2D) {
  VariableRegistry vars;
  const int one = add_group(vars, "flux", TensorKind::scalar, Centering::face_y);
  vars.group(one).ghosts = 1;
  Block b(0, 0, {0, 0, 0}, {8, 4, 1}, {3, 3, 0}, {0, 0, 0}, {1, 1, 1}, vars);
  EXPECT_EQ(b.group_extent(one), (std::array<int, 3>{10, 7, 1}));
  EXPECT_EQ(b.size(one), 70u);
}

TEST(Block, CellCentres) {
  VariableRegistry vars;
  Block b(0, 0, {1, 0, 0}, {4, 1, 1}, {2, 0, 0}, {0.5, 0, 0}, {0.25, 1, 1}, vars);
  EXPECT_DOUBLE_EQ(b.x(0, 0), 0.625);
  EXPECT_DOUBLE_EQ(b.x(0, -1), 0.375);
}

TEST(Block, ReductionKindNames) {
  EXPECT_STREQ(to_string(ReductionKind::norm2), "norm2");
  EXPECT_STREQ(to_string(ReductionKind::volume_integral), "volume_integral");
}

}  // namespace
}  // namespace remnant::grid::test
