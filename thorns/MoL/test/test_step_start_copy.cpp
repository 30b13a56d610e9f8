// Memory accounting of MoL's copy of the evolved groups at the start of a step (issue 21, goal 7):
// it holds the interior only. Before, it copied every point including ghosts: for one cell-centred
// component of a 16^3 block with 3 ghost layers that is 22^3 = 10648 points instead of 4096.
#include <gtest/gtest.h>

#include "remnant/grid.hpp"
#include "step_start_copy.hpp"

using namespace remnant;
using namespace remnant::mol;

namespace {
int add_group(VariableRegistry& vars, const std::string& name, Centering c, int ncomp) {
  VariableGroupSpec g;
  g.thorn = "Test";
  g.name = name;
  g.centering = c;
  for (int i = 0; i < ncomp; ++i) g.components.push_back({name + std::to_string(i)});
  return vars.add(g);
}
}  // namespace

TEST(StepStartCopy, HoldsTheInteriorOnlyAndReturnsItsRows) {
  VariableRegistry vars;
  const int cons = add_group(vars, "cons", Centering::cell, 6);
  const int bx = add_group(vars, "bx", Centering::face_x, 1);
  Block b(0, 0, {0, 0, 0}, {16, 16, 16}, {3, 3, 3}, {0, 0, 0}, {1, 1, 1}, vars);
  for (int g : {cons, bx})
    for (std::size_t p = 0; p < b.size(g); ++p) b.data(g)[p] = static_cast<double>(p) + 0.5;
  std::vector<Block*> blocks{&b};
  StepStartCopy copy;
  copy.save(blocks, {cons, bx}, vars);
  // 6 x 16^3 cells + 17 x 16^2 faces: 203,264 bytes (the whole arrays: 580,928).
  const std::size_t interior = (6 * 16 * 16 * 16 + 17 * 16 * 16) * sizeof(double);
  EXPECT_EQ(copy.bytes(), interior);
  EXPECT_EQ(interior_points(b, Centering::face_x), (std::array<int, 3>{17, 16, 16}));
  for (int c : {0, 5}) {
    const Field u = b.field(cons, c);
    const double* row = copy.row(b.gid, cons, c, 7, 15);
    for (int i = 0; i < 16; ++i) EXPECT_EQ(row[i], u(i, 7, 15));
  }
  const Field f = b.field(bx, 0);
  const double* row = copy.row(b.gid, bx, 0, 15, 3);
  for (int i = 0; i < 17; ++i) EXPECT_EQ(row[i], f(i, 15, 3));
  // A second save of the same blocks reuses the storage.
  copy.save(blocks, {cons, bx}, vars);
  EXPECT_EQ(copy.bytes(), interior);
}
