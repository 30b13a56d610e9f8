#pragma once
// Shared helpers of the Grid tests: a registry with one group per tensor kind, a smooth test
// function of the global cell index, and the value every ghost must hold after a synchronisation.
#include <array>
#include <cstdint>
#include <string>

#include "Grid/amr_grid.hpp"
#include "remnant/grid.hpp"
#include "remnant/variables.hpp"

namespace remnant::grid::test {

struct TestGroups {
  VariableRegistry vars;
  int scalar, vector, covector, axial, tensor_dd;
};
TestGroups make_test_groups();
int add_group(VariableRegistry& vars, const std::string& name, TensorKind kind,
              Centering centering = Centering::cell);

// A smooth function of the cell centre of global cell (I, J, K) (and of the component), computed
// from the index so that the same cell always gives the same bits.
double test_function(const GridConfig& c, int comp, std::array<std::int64_t, 3> global);

// Fills the interior of every block with test_function and the ghosts with NaN.
void fill_interior(AmrGrid& grid, const VariableRegistry& vars, int group);

// The value a point (interior or ghost) must hold after synchronize(): the test function at the
// image cell (wrapped, clamped or mirrored per direction), times the reflection parities.
double expected_value(const AmrGrid& grid, const ComponentSpec& comp, int comp_index,
                      std::array<std::int64_t, 3> global);

// Number of points (ghosts included, used directions only) whose value differs from expected;
// reports the first few through gtest.
std::int64_t count_wrong_points(AmrGrid& grid, const VariableRegistry& vars, int group,
                                double tolerance = 0.0);

}  // namespace remnant::grid::test
