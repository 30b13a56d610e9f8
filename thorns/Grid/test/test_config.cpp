// Grid settings: the thorn.yaml declarations, parameter reading, and clear errors.
#include <gtest/gtest.h>
#include <mpi.h>

#include <fstream>
#include <sstream>

#include "config.hpp"
#include "grid_test_util.hpp"
#include "remnant/parameters.hpp"
#include "remnant/thorn_spec.hpp"

namespace remnant::grid::test {
namespace {

std::string error_of(const GridConfig& c) {
  try {
    checked(c);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GridConfig, BlockSizeMustDivideCellsAndTheMessageNamesBoth) {
  GridConfig c;
  c.ncells = {32, 30, 32};
  const std::string e = error_of(c);
  EXPECT_NE(e.find("Grid::ncells[1] = 30"), std::string::npos) << e;
  EXPECT_NE(e.find("Grid::block_size[1] = 16"), std::string::npos) << e;
}

TEST(GridConfig, PeriodicOnOneSideOnlyIsAnError) {
  GridConfig c;
  c.boundary_lower[2] = Boundary::periodic;
  EXPECT_NE(error_of(c).find("periodic on one side only"), std::string::npos) << error_of(c);
}

TEST(GridConfig, OppositeAxialParityNeedsAReflectFace) {
  GridConfig c;
  c.axial_reflection[1] = AxialReflection::opposite;
  EXPECT_NE(error_of(c).find("Grid::axial_vector_reflection[1] = opposite, but direction 1 has no reflect face"), std::string::npos)
      << error_of(c);
  c.boundary_lower[1] = Boundary::reflect;
  c.xmin[1] = 0.0;
  EXPECT_EQ(error_of(c), "");
  c.dimension = 1;  // unused directions are ignored (reset to mirror)
  EXPECT_EQ(checked(c).axial_reflection[1], AxialReflection::mirror);
}

TEST(GridConfig, CurvilinearFacesNeedAxisAndOrigin) {
  GridConfig c;
  c.coordinates = CoordinateSystem::spherical;
  c.dimension = 2;
  c.ncells = {32, 16, 1};
  c.xmin = {0, 0, 0};
  c.xmax = {1, 3.141592653589793 / 2, 1};
  EXPECT_NE(error_of(c).find("Grid::boundary_lower[0] = outflow at r = 0"), std::string::npos) << error_of(c);
  c.boundary_lower = {Boundary::origin, Boundary::axis, Boundary::outflow};
  EXPECT_NE(error_of(c).find("theta must span [0, pi], or [0, pi/2]"), std::string::npos) << error_of(c);
  c.boundary_upper[1] = Boundary::reflect;
  EXPECT_EQ(error_of(c), "");
  const GridConfig k = checked(c);
  EXPECT_DOUBLE_EQ(k.xmax[2], 2 * 3.141592653589793) << "unused phi spans the circle";
  c.coordinates = CoordinateSystem::cartesian;
  c.xmin = {-1, -1, -1};
  EXPECT_NE(error_of(c).find("Cartesian coordinates have no axis or origin"), std::string::npos) << error_of(c);
}

TEST(GridConfig, RefinementNeedsEvenBlocksOfTwiceTheGhostWidth) {
  GridConfig c;
  c.ncells = {32, 32, 32};
  c.block_size = {8, 8, 8};
  c.ghost_zones = 3;
  c.max_level = 2;
  EXPECT_EQ(error_of(c), "");
  c.block_size = {4, 8, 8};
  EXPECT_NE(error_of(c).find("at least 2 * Grid::ghost_zones = 6"), std::string::npos) << error_of(c);
}

TEST(GridConfig, BlocksMustHoldTheGhostWidth) {
  GridConfig c;
  c.ncells = {32, 32, 32};
  c.block_size = {16, 2, 16};
  EXPECT_NE(error_of(c).find("smaller than Grid::ghost_zones = 3"), std::string::npos) << error_of(c);
}

TEST(GridConfig, EntriesBeyondTheDimensionAreIgnored) {
  GridConfig c;
  c.dimension = 1;
  c.ncells = {64, 30, 7};  // 30 and 7 would not divide by 16, but they are not used
  c.boundary_lower[1] = Boundary::periodic;
  const GridConfig k = checked(c);
  EXPECT_EQ(k.ncells, (std::array<std::int64_t, 3>{64, 1, 1}));
  EXPECT_EQ(k.block_size, (std::array<int, 3>{16, 1, 1}));
  EXPECT_EQ(k.boundary_lower[1], Boundary::outflow);
}

ThornSpec grid_thorn_spec() {
  const std::string path = std::string(REMNANT_SOURCE_DIR) + "/thorns/Grid/thorn.yaml";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return parse_thorn_spec(text.str(), "thorns/Grid/thorn.yaml");
}

TEST(GridConfig, ThornYamlDefaultsGiveTheDefaultConfig) {
  const ThornSpec spec = grid_thorn_spec();
  EXPECT_EQ(spec.provides, (std::vector<std::string>{"grid", "staggered_grid"}));
  Parameters params;
  for (const auto& p : spec.parameters) params.declare(p);
  const GridConfig c = config_from_parameters(params);
  const GridConfig d = checked(GridConfig{});
  EXPECT_EQ(c.coordinates, d.coordinates);
  EXPECT_EQ(c.dimension, d.dimension);
  EXPECT_EQ(c.ncells, d.ncells);
  EXPECT_EQ(c.block_size, d.block_size);
  EXPECT_EQ(c.xmin, d.xmin);
  EXPECT_EQ(c.xmax, d.xmax);
  EXPECT_EQ(c.ghost_zones, d.ghost_zones);
  EXPECT_EQ(c.boundary_lower, d.boundary_lower);
  EXPECT_EQ(c.boundary_upper, d.boundary_upper);

  VariableRegistry vars;
  AmrGrid grid(GridSetup{params, vars, MPI_COMM_SELF});
  EXPECT_EQ(grid.global_cells(), 32 * 32 * 32);
  EXPECT_EQ(grid.local_blocks().size(), 8u);
}

TEST(GridConfig, ParameterErrorsNameTheParfileLocation) {
  const ThornSpec spec = grid_thorn_spec();
  Parameters params;
  for (const auto& p : spec.parameters) params.declare(p);
  params.set("Grid", "block_size", std::vector<std::int64_t>{16, 12, 16}, {"run.yaml", 7, 15});
  try {
    config_from_parameters(params);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.yaml:7:15"), std::string::npos) << e.what();
  }
  params.set("Grid", "block_size", std::vector<std::int64_t>{16, 16, 16}, {"run.yaml", 7, 15});
  params.set("Grid", "coordinates", std::string("cylindrical"), {"run.yaml", 3, 16});
  params.set("Grid", "xmin", std::vector<double>{-1, -1, -1}, {"run.yaml", 4, 10});
  try {
    config_from_parameters(params);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.yaml:4:10"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("R cannot be negative"), std::string::npos) << e.what();
  }
}

// The thorn.yaml keyword reaches the config, and the domain given to other thorns carries it.
TEST(GridConfig, AxialVectorReflectionIsReadPerDirection) {
  const ThornSpec spec = grid_thorn_spec();
  Parameters params;
  for (const auto& p : spec.parameters) params.declare(p);
  params.set("Grid", "boundary_lower", std::vector<std::string>{"reflect", "reflect", "reflect"}, {"run.yaml", 2, 1});
  params.set("Grid", "xmin", std::vector<double>{0, 0, 0}, {"run.yaml", 3, 1});
  params.set("Grid", "axial_vector_reflection", std::vector<std::string>{"opposite", "opposite", "mirror"}, {"run.yaml", 4, 1});
  const GridConfig c = config_from_parameters(params);
  EXPECT_EQ(c.axial_reflection, (std::array<AxialReflection, 3>{AxialReflection::opposite, AxialReflection::opposite,
                                                                 AxialReflection::mirror}));
  VariableRegistry vars;
  AmrGrid grid(GridSetup{params, vars, MPI_COMM_SELF});
  EXPECT_EQ(grid.domain().faces.axial_reflection, c.axial_reflection);
}

TEST(GridConfig, DescribeAndSpacing) {
  GridConfig c;
  c.dimension = 2;
  c.ncells = {64, 32, 1};
  c.block_size = {16, 16, 1};
  c.boundary_lower[0] = c.boundary_upper[0] = Boundary::periodic;
  c.boundary_upper[1] = Boundary::reflect;
  VariableRegistry vars;
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  EXPECT_EQ(grid.dimension(), 2);
  EXPECT_EQ(grid.global_cells(), 64 * 32);
  EXPECT_DOUBLE_EQ(grid.min_spacing(), 2.0 / 64);
  const std::string d = grid.describe();
  EXPECT_NE(d.find("64 x 32 on level 0; 2048 in all"), std::string::npos) << d;
  EXPECT_NE(d.find("level 0     8 blocks, 2048 cells"), std::string::npos) << d;
  EXPECT_NE(d.find("x: periodic, y: outflow/reflect"), std::string::npos) << d;
}

}  // namespace
}  // namespace remnant::grid::test
