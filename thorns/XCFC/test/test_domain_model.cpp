// The shared domain model (remnant/domain.hpp) as the Grid and XCFC use it: the origin's map on an
// equatorial domain is the composition of the origin and equator maps the Grid used to apply one
// after the other; the Cartesian parities of a vector from its tensor type are XCFC's former
// hand-written table; cell images flip theta and turn phi; XCFC's check of the grid's faces.
#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>
#include <string>

#include "XCFC/multigrid/structured_grid.hpp"
#include "grid_bridge.hpp"
#include "remnant/domain.hpp"

namespace {

using namespace remnant;
using remnant::xcfc::GridShape;

DomainFaces spherical(int dim, bool equator) {
  DomainFaces f;
  f.coordinates = CoordinateSystem::spherical;
  f.dimension = dim;
  f.boundary[0] = {Boundary::origin, Boundary::outflow};
  f.boundary[1] = {Boundary::axis, equator ? Boundary::reflect : Boundary::axis};
  f.boundary[2] = {dim == 3 ? Boundary::periodic : Boundary::outflow, dim == 3 ? Boundary::periodic : Boundary::outflow};
  return f;
}

TEST(DomainModel, OriginOnAnEquatorialDomainIsTheOriginMapThenTheEquatorMirror) {
  for (int dim : {2, 3})
    for (int stagger_theta : {0, 1}) {
      const std::array<std::int64_t, 3> cells{16, 8, dim == 3 ? 16 : 1};
      const std::array<int, 3> stagger{0, stagger_theta, 0};
      // The Grid's former sequence: theta mirrored about pi (as on a [0, pi] domain), then the
      // equator's mirror brings it back.
      const DomainFaces full = spherical(dim, false), half = spherical(dim, true);
      IndexMap two;
      full.cross(two, 0, false, cells, 2 * cells[1], stagger);
      half.cross(two, 1, true, cells, 2 * cells[1], stagger);
      IndexMap one;
      half.cross(one, 0, false, cells, 2 * cells[1], stagger);
      EXPECT_EQ(one.sigma, two.sigma) << dim;
      EXPECT_EQ(one.shift, two.shift) << dim;
      EXPECT_EQ(one.basis_sign, two.basis_sign) << dim;
      EXPECT_EQ(one.mirrored, two.mirrored) << dim;
      EXPECT_EQ(one.sigma[1], 1);
      EXPECT_EQ(one.shift[1], 0);  // theta kept
    }
}

// XCFC's former table of the parities of B's Cartesian components (vector_poisson.cpp before the
// shared model).
double former_parity(const GridShape& s, int d, int side, int a) {
  switch (s.boundary[d][side]) {
    case Boundary::reflect: return (s.coordinates == CoordinateSystem::cartesian ? a == d : a == 2) ? -1 : 1;
    case Boundary::axis: return a < 2 && !s.turns_phi() ? -1 : 1;
    case Boundary::origin:
      if (s.turns_phi()) return a == 2 && !s.origin_flips_theta() ? -1 : 1;
      return s.dimension == 1 ? -1 : (a < 2 || !s.origin_flips_theta()) ? -1 : 1;
    default: return 1;
  }
}

TEST(DomainModel, CartesianVectorParitiesFromTheTensorTypeMatchXcfcsFormerTable) {
  std::vector<GridShape> shapes;
  for (int dim : {1, 2, 3})
    for (bool equator : {false, true}) {
      if (dim == 1 && equator) continue;
      GridShape s;
      const DomainFaces f = spherical(dim, equator);
      s.coordinates = f.coordinates, s.dimension = dim, s.boundary = f.boundary;
      s.n = {8, dim >= 2 ? 8 : 1, dim == 3 ? 8 : 1};
      shapes.push_back(s);
    }
  for (int dim : {2, 3}) {
    GridShape s;
    s.coordinates = CoordinateSystem::cylindrical, s.dimension = dim;
    s.boundary[0] = {Boundary::axis, Boundary::outer};
    s.boundary[1] = {Boundary::reflect, Boundary::outer};
    if (dim == 3) s.boundary[2] = {Boundary::periodic, Boundary::periodic};
    s.n = {8, 8, dim == 3 ? 8 : 1};
    shapes.push_back(s);
  }
  GridShape octant;
  octant.boundary = {{{Boundary::reflect, Boundary::outer}, {Boundary::reflect, Boundary::outer}, {Boundary::reflect, Boundary::outer}}};
  octant.n = {8, 8, 8};
  shapes.push_back(octant);
  const auto B = expand_tensor(TensorKind::vector, "B");
  int checked = 0;
  for (const GridShape& s : shapes)
    for (int d = 0; d < s.dimension; ++d)
      for (int side = 0; side < 2; ++side)
        for (int a = 0; a < 3; ++a, ++checked)
          EXPECT_EQ(cartesian_face_parity(s.faces(), d, side, B[static_cast<std::size_t>(a)], s.cell_counts()), former_parity(s, d, side, a))
              << "dimension " << s.dimension << " coordinates " << static_cast<int>(s.coordinates) << " face " << d << "/" << side
              << " component " << a;
  EXPECT_GT(checked, 100);
  // A scalar is even everywhere; an axial vector takes the isometry's determinant once more.
  const GridShape& eq2 = shapes[2];  // 2D spherical with the equator: the origin maps X to -X
  EXPECT_EQ(cartesian_face_parity(eq2.faces(), 0, 0, expand_tensor(TensorKind::scalar, "u")[0], eq2.cell_counts()), 1.0);
  EXPECT_EQ(cartesian_face_parity(eq2.faces(), 0, 0, B[2], eq2.cell_counts()), -1.0);
  EXPECT_EQ(cartesian_face_parity(eq2.faces(), 0, 0, expand_tensor(TensorKind::axial_vector, "b")[2], eq2.cell_counts()), 1.0);
}

TEST(DomainModel, CellImagesFlipThetaAndTurnPhiThroughTheOrigin) {
  GridShape s;
  const DomainFaces f = spherical(3, false);
  s.coordinates = f.coordinates, s.dimension = 3, s.boundary = f.boundary, s.n = {8, 6, 10};
  EXPECT_EQ(s.image({-1, 1, 2}, 0, 0), (std::array<long long, 3>{0, 4, 7}));
  EXPECT_EQ(s.image({-2, 0, 7}, 0, 0), (std::array<long long, 3>{1, 5, 2}));
  // Across the axis: theta mirrored about the axis, phi turned; other coordinates kept.
  EXPECT_EQ(s.image({3, -1, 9}, 1, 0), (std::array<long long, 3>{3, 0, 4}));
  EXPECT_EQ(s.image({-1, 6, 0}, 1, 1), (std::array<long long, 3>{-1, 5, 5}));
  // Periodic phi wraps.
  EXPECT_EQ(s.image({2, 3, -1}, 2, 0), (std::array<long long, 3>{2, 3, 9}));
  EXPECT_EQ(s.image({2, 3, 10}, 2, 1), (std::array<long long, 3>{2, 3, 0}));
}

TEST(DomainModel, XcfcTakesOnlyFacesWithAFarFieldOrAnImage) {
  Domain d;
  d.faces.coordinates = CoordinateSystem::cartesian;
  d.faces.dimension = 3;
  d.faces.boundary[0] = {Boundary::periodic, Boundary::periodic};
  d.lo = {0, 0, 0}, d.hi = {1, 1, 2 * std::numbers::pi};
  try {
    xcfc::check_face(d, 0, 0);
    FAIL() << "a periodic Cartesian face was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'periodic' in direction 0 is not supported"), std::string::npos) << e.what();
  }
  d.faces.coordinates = CoordinateSystem::spherical;
  d.faces.boundary = {{{Boundary::origin, Boundary::outflow}, {Boundary::axis, Boundary::axis}, {Boundary::periodic, Boundary::periodic}}};
  for (int dir = 0; dir < 3; ++dir)
    for (int side = 0; side < 2; ++side) EXPECT_NO_THROW(xcfc::check_face(d, dir, side));
  d.hi[2] = std::numbers::pi;  // a periodic phi over half the circle has no far field either
  EXPECT_THROW(xcfc::check_face(d, 2, 0), std::invalid_argument);
}

}  // namespace
