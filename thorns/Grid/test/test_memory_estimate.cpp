// The memory estimate that comes before any allocation (issue 16): its arithmetic, and the refusal
// of a grid above Flesh::max_memory_gb or the machine, naming the parameters.
#include <gtest/gtest.h>
#include <mpi.h>

#include <fstream>
#include <sstream>

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
  // 70 points with ghosts; u twice (state and Runge-Kutta copy), u_rhs once.
  EXPECT_DOUBLE_EQ(m.bytes_per_block, 70.0 * 8 * 3);
  EXPECT_EQ(m.blocks_per_rank, 4);
  EXPECT_DOUBLE_EQ(m.bytes_per_rank, 4 * 70.0 * 8 * 3 + 200.0 * 10);
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
