#include "grid_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace remnant::grid::test {

int add_group(VariableRegistry& vars, const std::string& name, TensorKind kind, Centering centering) {
  VariableGroupSpec g;
  g.thorn = "Test";
  g.name = name;
  g.centering = centering;
  g.components = expand_tensor(kind, name);
  return vars.add(std::move(g));
}

TestGroups make_test_groups() {
  TestGroups t;
  t.scalar = add_group(t.vars, "rho", TensorKind::scalar);
  t.vector = add_group(t.vars, "v", TensorKind::vector);
  t.covector = add_group(t.vars, "S", TensorKind::covector);
  t.axial = add_group(t.vars, "B", TensorKind::axial_vector);
  t.tensor_dd = add_group(t.vars, "gamma", TensorKind::tensor_dd);
  return t;
}

double test_function(const GridConfig& c, int comp, std::array<std::int64_t, 3> g) {
  double x[3];
  for (std::size_t d = 0; d < 3; ++d) {
    const double dx = (c.xmax[d] - c.xmin[d]) / static_cast<double>(c.ncells[d]);
    x[d] = c.xmin[d] + (static_cast<double>(g[d]) + 0.5) * dx;
  }
  // Neither even nor odd in any direction, so a wrong parity or image cell shows.
  return 1.0 + comp + 0.7 * x[0] + std::sin(1.3 * x[1] + 0.2) + 0.5 * std::cos(0.9 * x[2] - 0.4) +
         0.3 * x[0] * x[1] * x[2];
}

namespace {
template <class F>
void for_all_points(const Block& b, F&& f) {
  for (int k = -b.ng[2]; k < b.n[2] + b.ng[2]; ++k)
    for (int j = -b.ng[1]; j < b.n[1] + b.ng[1]; ++j)
      for (int i = -b.ng[0]; i < b.n[0] + b.ng[0]; ++i) f(i, j, k);
}

std::array<std::int64_t, 3> global_index(const Block& b, int i, int j, int k) {
  return {b.index[0] * b.n[0] + i, b.index[1] * b.n[1] + j, b.index[2] * b.n[2] + k};
}
}  // namespace

void fill_interior(AmrGrid& grid, const VariableRegistry& vars, int group) {
  for (Block* b : grid.local_blocks()) {
    for (int c = 0; c < vars.group(group).ncomp(); ++c) {
      Field f = b->field(group, c);
      for_all_points(*b, [&](int i, int j, int k) {
        const bool interior = i >= 0 && i < b->n[0] && j >= 0 && j < b->n[1] && k >= 0 && k < b->n[2];
        f(i, j, k) = interior ? test_function(grid.config(), c, global_index(*b, i, j, k))
                              : std::numeric_limits<double>::quiet_NaN();
      });
    }
  }
}

double expected_value(const AmrGrid& grid, const ComponentSpec& comp, int comp_index,
                      std::array<std::int64_t, 3> g) {
  const GridConfig& c = grid.config();
  double parity = 1.0;
  for (std::size_t d = 0; d < 3; ++d) {
    const std::int64_t n = c.ncells[d];
    if (g[d] >= 0 && g[d] < n) continue;
    const bool upper = g[d] >= n;
    const Boundary bc = upper ? c.boundary_upper[d] : c.boundary_lower[d];
    switch (bc) {
      case Boundary::periodic: g[d] = (g[d] % n + n) % n; break;
      case Boundary::outflow: g[d] = upper ? n - 1 : 0; break;
      case Boundary::reflect:
        g[d] = upper ? 2 * n - 1 - g[d] : -1 - g[d];
        parity *= comp.reflection_parity[d];
        break;
    }
  }
  return parity * test_function(c, comp_index, g);
}

std::int64_t count_wrong_points(AmrGrid& grid, const VariableRegistry& vars, int group,
                                double tolerance) {
  std::int64_t wrong = 0;
  for (Block* b : grid.local_blocks()) {
    const auto& spec = vars.group(group);
    for (int c = 0; c < spec.ncomp(); ++c) {
      Field f = b->field(group, c);
      const ComponentSpec& comp = spec.components[static_cast<std::size_t>(c)];
      for_all_points(*b, [&](int i, int j, int k) {
        const auto g = global_index(*b, i, j, k);
        const double want = expected_value(grid, comp, c, g);
        const double got = f(i, j, k);
        if (!(std::abs(got - want) <= tolerance)) {
          if (++wrong <= 5)
            ADD_FAILURE() << "block " << b->gid << " comp " << c << " point (" << i << "," << j << ","
                          << k << ") global (" << g[0] << "," << g[1] << "," << g[2] << "): got " << got
                          << ", want " << want;
        }
      });
    }
  }
  return wrong;
}

}  // namespace remnant::grid::test
