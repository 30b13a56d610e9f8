// The memory estimate that comes before any allocation (issue 16): its arithmetic, and the refusal
// of a grid above Flesh::max_memory_gb or the machine, naming the parameters.
#include <gtest/gtest.h>
#include <mpi.h>

#include <fstream>
#include <sstream>
#include <tuple>

#include "Grid/amr_grid.hpp"
#include "config.hpp"
#include "memory_estimate.hpp"
#include "remnant/parameters.hpp"
#include "remnant/thorn_spec.hpp"

using namespace remnant;
using namespace remnant::grid;

namespace {

ThornSpec spec_from(const std::string& relative) {
  std::ifstream in(std::string(REMNANT_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return parse_thorn_spec(text.str(), relative);
}

Parameters grid_and_flesh_parameters() {
  Parameters p;
  for (const char* f : {"framework/flesh.yaml", "thorns/Grid/thorn.yaml"})
    for (const auto& s : spec_from(f).parameters) p.declare(s);
  return p;
}

VariableRegistry evolved_scalar() {
  VariableRegistry vars;
  VariableGroupSpec u;
  u.thorn = "T";
  u.name = "u";
  u.components = expand_tensor(TensorKind::scalar, "u");
  u.role = VariableRole::evolved;
  u.rhs = "u_rhs";
  vars.add(u);
  VariableGroupSpec r = u;
  r.name = "u_rhs";
  r.role = VariableRole::auxiliary;
  r.rhs.clear();
  vars.add(r);
  vars.resolve_rhs();
  return vars;
}

}  // namespace

TEST(MemoryEstimate, CountsGhostsRungeKuttaCopiesAndTheForest) {
  GridConfig c;
  c.dimension = 1;
  c.ncells = {640, 1, 1};
  c.block_size = {64, 1, 1};
  c.xmin = {0, 0, 0};
  c.ghost_zones = 3;
  const GridConfig checked_config = checked(c);
  const VariableRegistry vars = evolved_scalar();
  EXPECT_EQ(level0_blocks(checked_config), 10);
  const MemoryEstimate m = estimate_memory(checked_config, vars, 10, 3);
  // 70 points with ghosts for u and u_rhs, and MoL's copy of u's 64 interior points (issue 21,
  // goal 7: it held the 70 before).
  EXPECT_DOUBLE_EQ(m.bytes_per_block, (70.0 + 70.0 + 64.0) * 8);
  EXPECT_EQ(m.blocks_per_rank, 4);
  EXPECT_DOUBLE_EQ(m.bytes_per_rank, 4 * (70.0 + 70.0 + 64.0) * 8 + 200.0 * 10);
  EXPECT_GT(machine_memory_bytes(), 1e8);
}

TEST(MemoryEstimate, RefusesAGridAboveTheLimitNamingTheParameters) {
  Parameters p = grid_and_flesh_parameters();
  const VariableRegistry vars = evolved_scalar();
  p.set("Grid", "ncells", std::vector<std::int64_t>{64, 64, 64}, {"run.yaml", 4, 11});
  p.set("Flesh", "max_memory_gb", 1e-4, {"run.yaml", 9, 18});
  try {
    memory_checked(config_from_parameters(p), vars, p, MPI_COMM_SELF);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("run.yaml:4:11: error: the grid needs about"), std::string::npos) << msg;
    EXPECT_NE(msg.find("but a rank may use 100 kB (Flesh::max_memory_gb)"), std::string::npos) << msg;
  }
  p.set("Flesh", "max_memory_gb", 1.0, {"run.yaml", 9, 18});
  EXPECT_NO_THROW(memory_checked(config_from_parameters(p), vars, p, MPI_COMM_SELF));
}

// The check runs in the constructor from parameters, before the forest or any block exists: a
// 10 TB grid is refused at once against the machine's memory.
TEST(MemoryEstimate, GridFromParametersRefusesTheMachineBeforeAllocating) {
  Parameters p = grid_and_flesh_parameters();
  const VariableRegistry vars = evolved_scalar();
  p.set("Grid", "ncells", std::vector<std::int64_t>{8192, 8192, 8192}, {"run.yaml", 4, 11});
  try {
    AmrGrid grid(GridSetup{p, vars, MPI_COMM_SELF});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("run.yaml:4:11"), std::string::npos) << msg;
    EXPECT_NE(msg.find("this machine's memory"), std::string::npos) << msg;
  }
}

// The per-group table of --print-grid (issue 21, goal 7) is what a Block allocates: staggered
// points and ghosts included, in 3D, and MoL's copy counts the interior of evolved groups only.
TEST(MemoryEstimate, GroupTableMatchesTheBlockAllocation) {
  GridConfig c;
  c.dimension = 3;
  c.ncells = {32, 32, 32};
  c.block_size = {16, 16, 16};
  c.ghost_zones = 3;
  VariableRegistry vars = evolved_scalar();
  VariableGroupSpec face;
  face.thorn = "T";
  face.name = "bx";
  face.centering = Centering::face_x;
  face.components = expand_tensor(TensorKind::scalar, "bx");
  vars.add(face);
  const auto groups = group_memory(c, vars);
  ASSERT_EQ(groups.size(), 3u);
  Block b(0, 0, {0, 0, 0}, {16, 16, 16}, {3, 3, 3}, {0, 0, 0}, {1, 1, 1}, vars);
  for (int g = 0; g < vars.size(); ++g)
    EXPECT_DOUBLE_EQ(groups[static_cast<std::size_t>(g)].bytes, static_cast<double>(b.size(g) * sizeof(double)));
  EXPECT_EQ(groups[0].name, "T::u");
  EXPECT_DOUBLE_EQ(groups[0].runge_kutta_bytes, 16.0 * 16 * 16 * 8);
  EXPECT_DOUBLE_EQ(groups[1].runge_kutta_bytes, 0.0);
  EXPECT_DOUBLE_EQ(groups[2].interior_bytes, 17.0 * 16 * 16 * 8);
  const std::string table = format_group_memory(c, vars);
  // u: (22^3 + 16^3) x 8 bytes over 16^3 cells; all: (22^3 + 22^3 + 23 x 22^2 + 16^3) x 8 / 16^3.
  EXPECT_NE(table.find("T::u"), std::string::npos) << table;
  EXPECT_NE(table.find("       29 B/cell (+RK)"), std::string::npos) << table;
  EXPECT_NE(table.find("       71 B/cell\n"), std::string::npos) << table;
}

// Groups that declare fewer ghosts (thorn.yaml `ghosts`) count with them, as the Block allocates.
TEST(MemoryEstimate, GroupTableCountsEachGroupsOwnGhosts) {
  GridConfig c;
  c.dimension = 3;
  c.ncells = {32, 32, 32};
  c.block_size = {16, 16, 16};
  c.ghost_zones = 3;
  VariableRegistry vars;
  for (const auto& [name, centering, ghosts] :
       {std::tuple{"bx", Centering::face_x, 0}, std::tuple{"f", Centering::face_y, 1}, std::tuple{"h", Centering::cell, 2}}) {
    VariableGroupSpec g;
    g.thorn = "T";
    g.name = name;
    g.centering = centering;
    g.ghosts = ghosts;
    g.components = expand_tensor(TensorKind::scalar, name);
    vars.add(g);
  }
  const auto groups = group_memory(c, vars);
  Block b(0, 0, {0, 0, 0}, {16, 16, 16}, {3, 3, 3}, {0, 0, 0}, {1, 1, 1}, vars);
  for (int g = 0; g < vars.size(); ++g)
    EXPECT_DOUBLE_EQ(groups[static_cast<std::size_t>(g)].bytes, static_cast<double>(b.size(g) * sizeof(double)));
  EXPECT_DOUBLE_EQ(groups[0].bytes, 17.0 * 16 * 16 * 8);
  EXPECT_DOUBLE_EQ(groups[1].bytes, 18.0 * 19 * 18 * 8);
  EXPECT_DOUBLE_EQ(groups[2].bytes, 20.0 * 20 * 20 * 8);
}
