// Coordinates: exact volumes in every system, and ghost filling at axes, the origin and the
// equator with the signs that follow from the tensor types (a Cartesian field written in
// cylindrical or spherical components must come out right in every ghost).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "forest.hpp"
#include "grid_test_util.hpp"

namespace remnant::grid::test {
namespace {

constexpr double kPi = std::numbers::pi;
using CartesianField = std::function<Matrix3(const Point3& X)>;  // row 0: vector, 1: axial, 2: scalar/extra

GridConfig cylindrical(int dim) {
  GridConfig c;
  c.coordinates = CoordinateSystem::cylindrical;
  c.dimension = dim;
  c.ncells = {16, 16, 16};
  c.block_size = {8, 8, 8};
  c.ghost_zones = 3;
  c.xmin = {0, -1, 0};
  c.xmax = {2, 1, 2 * kPi};
  c.boundary_lower = {Boundary::axis, Boundary::outflow, Boundary::periodic};
  c.boundary_upper = {Boundary::outflow, Boundary::outflow, Boundary::periodic};
  return c;
}

GridConfig spherical(int dim, bool equator) {
  GridConfig c;
  c.coordinates = CoordinateSystem::spherical;
  c.dimension = dim;
  c.ncells = {16, 16, 16};
  c.block_size = {8, 8, 8};
  c.ghost_zones = 3;
  c.xmin = {0, 0, 0};
  c.xmax = {2, equator ? kPi / 2 : kPi, 2 * kPi};
  c.boundary_lower = {Boundary::origin, Boundary::axis, Boundary::periodic};
  c.boundary_upper = {Boundary::outflow, equator ? Boundary::reflect : Boundary::axis, Boundary::periodic};
  return c;
}

// Chart components at coordinates x of a Cartesian field: scalar s(X), vectors V(X) and B(X)
// (axial), covector W(X) = V(X), tensor T(X) (lower indices).
struct Fields {
  std::function<double(const Point3&)> scalar;
  std::function<Point3(const Point3&)> vector, axial;
  std::function<Matrix3(const Point3&)> tensor;
};

double chart_value(CoordinateSystem cs, const Fields& f, const VariableGroupSpec& spec, int comp, const Point3& x) {
  const Point3 X = coords::to_cartesian(cs, x);
  // `basis: cartesian`: the components along x, y, z whatever the grid's coordinates.
  if (spec.cartesian_basis) return f.vector(X)[static_cast<std::size_t>(comp)];
  switch (spec.components[static_cast<std::size_t>(comp)].kind) {
    case TensorKind::scalar: return f.scalar(X);
    case TensorKind::vector: return coords::vector_from_cartesian(cs, x, f.vector(X))[static_cast<std::size_t>(comp)];
    case TensorKind::axial_vector: return coords::vector_from_cartesian(cs, x, f.axial(X))[static_cast<std::size_t>(comp)];
    case TensorKind::covector: return coords::covector_from_cartesian(cs, x, f.vector(X))[static_cast<std::size_t>(comp)];
    case TensorKind::tensor_dd: {
      static const int ab[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
      const Matrix3 J = coords::jacobian(cs, x);
      const Matrix3 T = f.tensor(X);
      const int a = ab[comp][0], b = ab[comp][1];
      double s = 0;
      for (int A = 0; A < 3; ++A)
        for (int B = 0; B < 3; ++B) s += J[A][a] * J[B][b] * T[A][B];
      return s;
    }
    default: return 0;
  }
}

// Fills the interior with the chart components, ghosts with NaN; synchronises; compares every
// ghost that is not beyond an outflow face with the chart components at its (extended) centroid.
void expect_ghosts_match(const GridConfig& c, const Fields& f, MPI_Comm comm = MPI_COMM_SELF) {
  TestGroups t = make_test_groups();
  const int cartesian = add_group(t.vars, "v_cartesian", TensorKind::vector);
  t.vars.group(cartesian).cartesian_basis = true;
  AmrGrid grid(c, t.vars, comm);
  const std::vector<int> groups = {t.scalar, t.vector, t.covector, t.axial, t.tensor_dd, cartesian};
  const CoordinateSystem cs = c.coordinates;
  for (int g : groups) {
    const auto& spec = t.vars.group(g);
    for (Block* b : grid.local_blocks())
      for (int comp = 0; comp < spec.ncomp(); ++comp) {
        Field u = b->field(g, comp);
        for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
          for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
            for (int i = -b->ng[0]; i < b->n[0] + b->ng[0]; ++i) {
              const bool inside = i >= 0 && i < b->n[0] && j >= 0 && j < b->n[1] && k >= 0 && k < b->n[2];
              u(i, j, k) = inside ? chart_value(cs, f, spec, comp,
                                                {b->centroid(0, i), b->centroid(1, j), b->centroid(2, k)})
                                  : std::nan("");
            }
      }
  }
  grid.synchronize(groups);
  std::int64_t wrong = 0, checked_points = 0;
  for (int g : groups) {
    const auto& spec = t.vars.group(g);
    for (Block* b : grid.local_blocks()) {
      const auto nb = grid.forest().blocks_on_level(b->level);
      for (int comp = 0; comp < spec.ncomp(); ++comp) {
        Field u = b->field(g, comp);
        for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
          for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
            for (int i = -b->ng[0]; i < b->n[0] + b->ng[0]; ++i) {
              const int idx[3] = {i, j, k};
              bool beyond_outflow = false;
              for (int d = 0; d < c.dimension; ++d) {
                const auto ud = static_cast<std::size_t>(d);
                if (idx[d] < 0 && b->index[ud] == 0 && c.boundary_lower[ud] == Boundary::outflow) beyond_outflow = true;
                if (idx[d] >= b->n[ud] && b->index[ud] == nb[ud] - 1 && c.boundary_upper[ud] == Boundary::outflow)
                  beyond_outflow = true;
              }
              if (beyond_outflow) continue;
              const double want = chart_value(cs, f, spec, comp,
                                              {b->centroid(0, i), b->centroid(1, j), b->centroid(2, k)});
              const double got = u(i, j, k);
              ++checked_points;
              if (!(std::abs(got - want) <= 1e-12 * (1 + std::abs(want)))) {
                if (++wrong <= 5)
                  ADD_FAILURE() << spec.full_name() << "." << spec.components[static_cast<std::size_t>(comp)].name
                                << " block " << b->gid << " point (" << i << "," << j << "," << k << ") at ("
                                << b->centroid(0, i) << ", " << b->centroid(1, j) << ", " << b->centroid(2, k)
                                << "): got " << got << ", want " << want;
              }
            }
      }
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(checked_points, 0);
}

// A constant Cartesian vector and tensor, a linear scalar: any 3D grid.
Fields constant_fields() {
  Fields f;
  f.scalar = [](const Point3& X) { return 1 + 0.3 * X[0] - 0.2 * X[1] + 0.4 * X[2]; };
  f.vector = [](const Point3&) { return Point3{0.3, -0.8, 0.5}; };
  f.axial = [](const Point3&) { return Point3{-0.6, 0.1, 0.9}; };
  f.tensor = [](const Point3&) { return Matrix3{{{1.1, 0.2, -0.3}, {0.2, 0.9, 0.4}, {-0.3, 0.4, 1.3}}}; };
  return f;
}

// Axisymmetric fields (rotation about z plus a radial part), symmetric under z -> -z as polar
// and axial quantities respectively: valid for 2D grids and the equator.
Fields axisymmetric_fields() {
  Fields f;
  f.scalar = [](const Point3& X) { return 1 + X[0] * X[0] + X[1] * X[1] + 0.5 * X[2] * X[2]; };
  f.vector = [](const Point3& X) { return Point3{0.7 * X[0] - 0.3 * X[1], 0.7 * X[1] + 0.3 * X[0], 0.5 * X[2]}; };
  f.axial = [](const Point3& X) { return Point3{0.4 * X[0] * X[2], 0.4 * X[1] * X[2], 0.8}; };
  f.tensor = [](const Point3& X) {
    Matrix3 T{};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) T[a][b] = (a == b ? 1.5 : 0.0) + 0.3 * X[a] * X[b];
    return T;
  };
  return f;
}

TEST(Parity, CylindricalAxis2D) { expect_ghosts_match(cylindrical(2), axisymmetric_fields()); }
TEST(Parity, CylindricalAxis3D) { expect_ghosts_match(cylindrical(3), constant_fields()); }
TEST(Parity, CylindricalAxisAndEquator2D) {
  GridConfig c = cylindrical(2);
  c.xmin[1] = 0;
  c.boundary_lower[1] = Boundary::reflect;
  expect_ghosts_match(c, axisymmetric_fields());
}
TEST(Parity, SphericalOrigin1D) { expect_ghosts_match(spherical(1, false), axisymmetric_fields()); }
TEST(Parity, SphericalOriginAndAxes2D) { expect_ghosts_match(spherical(2, false), axisymmetric_fields()); }
TEST(Parity, SphericalOriginAxisAndEquator2D) { expect_ghosts_match(spherical(2, true), axisymmetric_fields()); }
TEST(Parity, SphericalOriginAndAxes3D) { expect_ghosts_match(spherical(3, false), constant_fields()); }
TEST(Parity, CartesianOctant3D) {
  GridConfig c;
  c.ncells = {16, 16, 16};
  c.block_size = {8, 8, 8};
  c.xmin = {0, 0, 0};
  c.xmax = {1, 1, 1};
  c.boundary_lower = {Boundary::reflect, Boundary::reflect, Boundary::reflect};
  // Octant symmetry: the fields must be mirror-symmetric in x, y and z.
  Fields f;
  f.scalar = [](const Point3& X) { return 1 + X[0] * X[0] + 2 * X[1] * X[1] + 3 * X[2] * X[2]; };
  f.vector = [](const Point3& X) { return Point3{X[0], 2 * X[1], 3 * X[2]}; };
  f.axial = [](const Point3& X) { return Point3{X[1] * X[2], X[0] * X[2], X[0] * X[1]}; };
  f.tensor = [](const Point3& X) {
    Matrix3 T{};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) T[a][b] = (a == b ? 1.0 : 0.0) + X[a] * X[b];
    return T;
  };
  expect_ghosts_match(c, f);
}

// Grid::axial_vector_reflection = opposite: axial fields that are minus their pseudo-vector mirror
// image across the planes (a poloidal field about z across x = 0, y = 0; a toroidal field symmetric
// in z across the equator, also through the spherical origin's image). Polar fields unchanged.
TEST(Parity, CartesianOctantOppositeAxialParity3D) {
  GridConfig c;
  c.ncells = {16, 16, 16};
  c.block_size = {8, 8, 8};
  c.xmin = {0, 0, 0};
  c.xmax = {1, 1, 1};
  c.boundary_lower = {Boundary::reflect, Boundary::reflect, Boundary::reflect};
  c.axial_reflection = {AxialReflection::opposite, AxialReflection::opposite, AxialReflection::mirror};
  Fields f = axisymmetric_fields();  // its axial field is poloidal-like: (x z, y z, const)
  f.vector = [](const Point3& X) { return Point3{X[0], 2 * X[1], 3 * X[2]}; };
  expect_ghosts_match(c, f);
}
Fields toroidal_fields() {
  Fields f = axisymmetric_fields();
  f.axial = [](const Point3& X) {
    const double g = 1 + X[2] * X[2] + 0.5 * (X[0] * X[0] + X[1] * X[1]);
    return Point3{-X[1] * g, X[0] * g, 0.0};
  };
  return f;
}
TEST(Parity, CylindricalEquatorOppositeAxialParity2D) {
  GridConfig c = cylindrical(2);
  c.xmin[1] = 0;
  c.boundary_lower[1] = Boundary::reflect;
  c.axial_reflection[1] = AxialReflection::opposite;
  expect_ghosts_match(c, toroidal_fields());
}
TEST(Parity, SphericalOriginAndEquatorOppositeAxialParity2D) {
  GridConfig c = spherical(2, true);
  c.axial_reflection[1] = AxialReflection::opposite;
  expect_ghosts_match(c, toroidal_fields());
}

// Sum of the exact cell volumes against the domain volume.
double total_volume(const GridConfig& c) {
  VariableRegistry vars;
  const int u = add_group(vars, "one", TensorKind::scalar);
  AmrGrid grid(c, vars, MPI_COMM_SELF);
  for (Block* b : grid.local_blocks()) for_interior(*b, [&](int i, int j, int k) { b->field(u, 0)(i, j, k) = 1; });
  return grid.reduce(u, 0, ReductionKind::volume_integral);
}

TEST(Volumes, SumToTheDomainVolume) {
  const double R = 2, H = 2;
  EXPECT_NEAR(total_volume(cylindrical(1)) / (kPi * R * R), 1, 1e-14) << "1D: per unit length in z";
  EXPECT_NEAR(total_volume(cylindrical(2)) / (kPi * R * R * H), 1, 1e-14);
  EXPECT_NEAR(total_volume(cylindrical(3)) / (kPi * R * R * H), 1, 1e-14);
  const double ball = 4.0 / 3.0 * kPi * 8;
  EXPECT_NEAR(total_volume(spherical(1, false)) / ball, 1, 1e-14);
  EXPECT_NEAR(total_volume(spherical(2, false)) / ball, 1, 1e-14);
  EXPECT_NEAR(total_volume(spherical(2, true)) / (ball / 2), 1, 1e-14);
  EXPECT_NEAR(total_volume(spherical(3, false)) / ball, 1, 1e-14);
  GridConfig shell = spherical(2, true);
  shell.xmin[0] = 0.5;
  shell.boundary_lower[0] = Boundary::outflow;
  EXPECT_NEAR(total_volume(shell) / (2.0 / 3.0 * kPi * (8 - 0.125)), 1, 1e-14);
  // With refinement: the paper's spherical layout (a refined shell around a coarse core block).
  GridConfig amr = spherical(2, true);
  amr.ncells = {32, 16, 1};
  amr.max_level = 2;
  amr.regions = {{RegionKind::shell, RegionMode::at_least, 2, {0.5, 1.0, 0, 0, 0, 0}},
                 {RegionKind::sphere, RegionMode::at_most, 1, {0, 0.5, 0, 0, 0, 0}}};
  EXPECT_NEAR(total_volume(amr) / (ball / 2), 1, 1e-14);
  GridConfig cart;
  cart.ncells = {16, 16, 16};
  cart.block_size = {8, 8, 8};
  cart.max_level = 1;
  cart.regions = {{RegionKind::sphere, RegionMode::at_least, 1, {0, 0.3, 0, 0, 0, 0}}};
  EXPECT_NEAR(total_volume(cart) / 8.0, 1, 1e-14);
}

TEST(Coordinates, ChristoffelsAreThoseOfTheMetric) {
  // Gamma^a_bc = 1/2 f^aa (d_b f_ac + d_c f_ab - d_a f_bc) for a diagonal metric, by differences.
  for (CoordinateSystem cs : {CoordinateSystem::cylindrical, CoordinateSystem::spherical}) {
    const Point3 x{1.3, 0.7, 0.4};
    const Christoffels G = coords::christoffels(cs, x);
    const double h = 1e-6;
    auto df = [&](int d, int a) {
      Point3 p = x, m = x;
      p[static_cast<std::size_t>(d)] += h;
      m[static_cast<std::size_t>(d)] -= h;
      return (coords::metric_diagonal(cs, p)[static_cast<std::size_t>(a)] - coords::metric_diagonal(cs, m)[static_cast<std::size_t>(a)]) / (2 * h);
    };
    const Point3 f = coords::metric_diagonal(cs, x);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int c = 0; c < 3; ++c) {
          double want = 0;
          if (a == c) want += df(b, a);
          if (a == b) want += df(c, a);
          if (b == c) want -= df(a, b);
          want *= 0.5 / f[static_cast<std::size_t>(a)];
          EXPECT_NEAR(G[a][b][c], want, 1e-8) << to_string(cs) << " Gamma^" << a << "_" << b << c;
        }
  }
}

}  // namespace
}  // namespace remnant::grid::test
