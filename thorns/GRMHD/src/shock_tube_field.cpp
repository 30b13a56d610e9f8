#include "shock_tube_field.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/vector_potential.hpp"
#include "interior_faces.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/error.hpp"

namespace remnant::grmhd {

namespace {
constexpr int kEdgeQuadraturePoints = 8;  // exact to degree 15; sin^2 over pi/8 to ~1e-26
}  // namespace

CovariantPotential uniform_z_potential(CoordinateSystem cs, double b) {
  switch (cs) {
    case CoordinateSystem::cartesian:
      return [b](const Point3& x) { return std::array<double, 3>{-0.5 * b * x[1], 0.5 * b * x[0], 0.0}; };
    case CoordinateSystem::cylindrical:
      return [b](const Point3& x) { return std::array<double, 3>{0.0, 0.0, 0.5 * b * x[0] * x[0]}; };
    case CoordinateSystem::spherical:
      return [b](const Point3& x) {
        const double s = std::sin(x[1]);
        return std::array<double, 3>{0.0, 0.0, 0.5 * b * x[0] * x[0] * s * s};
      };
  }
  return {};
}

CovariantPotential uniform_x_potential(CoordinateSystem cs, double b) {
  switch (cs) {
    case CoordinateSystem::cartesian:
      return [b](const Point3& x) { return std::array<double, 3>{0.0, 0.0, b * x[1]}; };
    case CoordinateSystem::cylindrical:  // A_z = b y = b R sin phi
      return [b](const Point3& x) { return std::array<double, 3>{0.0, b * x[0] * std::sin(x[2]), 0.0}; };
    case CoordinateSystem::spherical:  // A_z = b y in (r, theta, phi) components
      return [b](const Point3& x) {
        const double st = std::sin(x[1]), ct = std::cos(x[1]), sp = std::sin(x[2]);
        return std::array<double, 3>{b * x[0] * st * sp * ct, -b * x[0] * x[0] * st * st * sp, 0.0};
      };
  }
  return {};
}

CovariantPotential test_potential(CoordinateSystem cs, double a0) {
  constexpr double k = 2 * std::numbers::pi;
  switch (cs) {
    case CoordinateSystem::cartesian:
      return [a0](const Point3& x) {
        const double sx = std::sin(k * x[0]), sy = std::sin(k * x[1]), sz = std::sin(k * x[2]);
        return std::array<double, 3>{a0 * sy * sz, a0 * sz * sx, a0 * sx * sy};
      };
    case CoordinateSystem::cylindrical:
      return [a0](const Point3& x) {
        const double R2 = x[0] * x[0];
        return std::array<double, 3>{0.0, a0 * x[0] * std::sin(x[2]), a0 * R2 * std::cos(k * x[1])};
      };
    case CoordinateSystem::spherical:
      return [a0](const Point3& x) {
        const double r2 = x[0] * x[0], s = std::sin(x[1]);
        return std::array<double, 3>{a0 * r2 * std::cos(x[1]), 0.0, a0 * r2 * s * s * std::cos(k * x[0])};
      };
  }
  return {};
}

void add_potential_field(const CovariantPotential& A, const std::array<int, 3>& bface, Block& b, int ghost_layers) {
  bool used[3];
  for (int d = 0; d < 3; ++d) used[d] = direction_used(b, d);
  // Gauss-Legendre along each edge, accurate to round-off for these smooth potentials: a coarse
  // edge's integral then equals the sum of its two fine halves, so coarse and fine faces carry the
  // same flux from t = 0 (the midpoint rule left 4e-5..2e-3 of the flux between levels).
  std::vector<double> nodes, weights;
  hydrobase::gauss_legendre(kEdgeQuadraturePoints, nodes, weights);
  // (R, z, phi) is a left-handed order: its circulations take a minus sign so that a potential
  // gives the same physical field in every coordinate system (as HydroBase/vector_potential.hpp).
  const double orientation = b.coordinates == CoordinateSystem::cylindrical ? -1.0 : 1.0;
  // The line integral of A_c along the edge of direction c at face indices id (cell id[c]).
  auto line = [&](int c, const int* id) {
    Point3 x{};
    for (int d = 0; d < 3; ++d) x[d] = d == c ? b.x(d, id[d]) : b.face_coordinate(d, id[d]);
    if (!used[c]) return A(x)[c] * b.volume_weight(c, 0);
    return hydrobase::gauss_line_integral(A, x, c, b.face_coordinate(c, id[c]), b.face_coordinate(c, id[c] + 1),
                                          nodes, weights);
  };
  for (int a = 0; a < 3; ++a) {
    const int bb = (a + 1) % 3, c = (a + 2) % 3;
    const Field f = b.field(bface[a], 0);
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      lo[d] = used[d] ? -ghost_layers : 0;
      hi[d] = b.n[d] + (used[d] ? ghost_layers + (a == d) : 0);
    }
    int id[3];
    for (id[2] = lo[2]; id[2] < hi[2]; ++id[2])
      for (id[1] = lo[1]; id[1] < hi[1]; ++id[1])
        for (id[0] = lo[0]; id[0] < hi[0]; ++id[0]) {
          // Phi_a = d_b A_c - d_c A_b around the face.
          double flux = 0;
          if (used[bb]) {
            int up[3] = {id[0], id[1], id[2]};
            ++up[bb];
            flux += line(c, up) - line(c, id);
          }
          if (used[c]) {
            int up[3] = {id[0], id[1], id[2]};
            ++up[c];
            flux -= line(bb, up) - line(bb, id);
          }
          const double area = b.face_area(a, id[0], id[1], id[2]);
          f(id[0], id[1], id[2]) += area > 0 ? orientation * flux / area : 0.0;
        }
  }
}

void shock_tube_field(Context& ctx) {
  const auto& left = ctx.param<std::vector<double>>("GRMHD", "shock_field_left");
  const auto& right = ctx.param<std::vector<double>>("GRMHD", "shock_field_right");
  if (left[0] != right[0])
    throw InputError(ctx.params().origin("GRMHD", "shock_field_right"),
                     "GRMHD::shock_field_left[0] and shock_field_right[0] (B^1, normal to the discontinuity) must be equal: a jump is not divergence-free");
  const double x0 = ctx.param<double>("GRMHD", "shock_position");
  const double a0 = ctx.param<double>("GRMHD", "field_potential_amplitude");
  const hydrobase::FieldGroups g = hydrobase::FieldGroups::of(ctx);
  const std::string& kind = ctx.param<std::string>("GRMHD", "field_potential");
  const CovariantPotential A = kind == "uniform_z"   ? uniform_z_potential(ctx.grid().coordinates(), a0)
                               : kind == "uniform_x" ? uniform_x_potential(ctx.grid().coordinates(), a0)
                                                     : test_potential(ctx.grid().coordinates(), a0);
  for (Block* b : ctx.grid().local_blocks()) {
    for (int a = 0; a < 3; ++a) {
      const Field f = b->field(g.bface[a], 0);
      for_interior_faces(*b, a, [&](int i, int j, int k) {
        // x faces take the left value at and left of x0 (B^1 is equal anyway); the others their cell's.
        const double x = a == 0 ? b->face_coordinate(0, i) : b->x(0, i);
        f(i, j, k) = (x < x0 ? left : right)[static_cast<std::size_t>(a)];
      });
    }
    if (a0 != 0) add_potential_field(A, g.bface, *b);
  }
}

}  // namespace remnant::grmhd
