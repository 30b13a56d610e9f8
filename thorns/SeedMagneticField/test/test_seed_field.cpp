// SeedMagneticField's pieces on Blocks built here: the interpolation of cell data, the two laws,
// the poloidal faces of a star-like pressure (divergence at round-off, the field it should be) and
// the toroidal phi faces.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "HydroBase/vector_potential.hpp"
#include "cell_interpolation.hpp"
#include "field_laws.hpp"
#include "seed_field.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"

namespace remnant::seed {
namespace {

constexpr double kPi = std::numbers::pi;

// One block of n^2 (2D, phi unused) or n^3 cells with the star's cell fields and the face fields.
struct StarBlock {
  VariableRegistry vars;
  int cell = -1, face[3] = {-1, -1, -1};
  std::unique_ptr<Block> block;
  StarBlock(CoordinateSystem c, int dim, int n, Point3 xmin, Point3 xmax) {
    VariableGroupSpec g;
    g.thorn = "Test";
    g.name = "star";
    g.components = expand_tensor(TensorKind::scalar, "rho");
    for (const char* extra : {"eps", "press", "alpha", "psi"}) g.components.push_back(expand_tensor(TensorKind::scalar, extra)[0]);
    cell = vars.add(std::move(g));
    const Centering cs[3] = {Centering::face_x, Centering::face_y, Centering::face_z};
    for (int d = 0; d < 3; ++d) {
      VariableGroupSpec f;
      f.thorn = "Test";
      f.name = "B" + std::to_string(d + 1);
      f.centering = cs[d];
      f.components = expand_tensor(TensorKind::scalar, f.name);
      face[d] = vars.add(std::move(f));
    }
    std::array<int, 3> cells{1, 1, 1}, ghosts{0, 0, 0};
    std::array<double, 3> dx{};
    for (int d = 0; d < 3; ++d) {
      const auto u = static_cast<std::size_t>(d);
      if (d >= dim) xmin[u] = 0, xmax[u] = (c == CoordinateSystem::spherical && d == 1) ? kPi : 2 * kPi;
      else cells[u] = n, ghosts[u] = 2;
      dx[u] = (xmax[u] - xmin[u]) / cells[u];
    }
    block = std::make_unique<Block>(0, 0, std::array<std::int64_t, 3>{0, 0, 0}, cells, ghosts, xmin, dx, vars);
    block->set_geometry(c, xmin);
  }
  Field at(int comp) { return block->field(cell, comp); }
  StarFields star() { return {at(0), at(1), at(2), at(3), at(4)}; }
  std::array<Field, 3> faces() { return {block->field(face[0], 0), block->field(face[1], 0), block->field(face[2], 0)}; }
  // Fills every cell (ghosts too) with f(Cartesian position of the cell midpoint) for component comp.
  template <class F>
  void fill(int comp, F f) {
    const Block& b = *block;
    Field u = at(comp);
    for (int k = -b.ng[2]; k < b.n[2] + b.ng[2]; ++k)
      for (int j = -b.ng[1]; j < b.n[1] + b.ng[1]; ++j)
        for (int i = -b.ng[0]; i < b.n[0] + b.ng[0]; ++i)
          u(i, j, k) = f(coords::to_cartesian(b.coordinates, {b.x(0, i), b.x(1, j), b.x(2, k)}));
  }
};

TEST(SeedMagneticField, InterpolationIsExactForLinearDataAndAveragesAtVertices) {
  StarBlock s(CoordinateSystem::cartesian, 3, 6, {-1, -1, -1}, {1, 1, 1});
  const Block& b = *s.block;
  Field u = s.at(2);
  for (int k = -2; k < 8; ++k)
    for (int j = -2; j < 8; ++j)
      for (int i = -2; i < 8; ++i) u(i, j, k) = 1.0 + 2.0 * b.x(0, i) - 0.5 * b.x(1, j) + 0.25 * b.x(2, k);
  const CellInterpolator p(b, u);
  for (const Point3 x : {Point3{0.1, -0.7, 0.33}, Point3{-1.0, 1.0, 0.0}, Point3{0.999, -0.2, -1.0}})
    EXPECT_NEAR(p(x), 1.0 + 2.0 * x[0] - 0.5 * x[1] + 0.25 * x[2], 1e-13);
  // At a vertex: the mean of the eight cells around it.
  const Point3 v{b.face_coordinate(0, 3), b.face_coordinate(1, 2), b.face_coordinate(2, 4)};
  double mean = 0;
  for (int c = 0; c < 8; ++c) mean += u(2 + (c & 1), 1 + ((c >> 1) & 1), 3 + ((c >> 2) & 1)) / 8;
  EXPECT_NEAR(p(v), mean, 1e-14);
}

TEST(SeedMagneticField, PoloidalLawVanishesBelowTheCut) {
  const PoloidalLaw law{2.0, 0.1, 2.0};
  EXPECT_EQ(law.a_phi(3.0, 0.05), 0.0);
  EXPECT_EQ(law.a_phi(3.0, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(law.a_phi(3.0, 0.3), 2.0 * 9.0 * 0.04);
}

TEST(SeedMagneticField, ToroidalLawMatchesThePapersMagnitude) {
  // B = sqrt(B_i B^i) = sqrt(g_phiphi) B^phi with g_phiphi = psi^4 R^2: psi^6 B^phi = psi^4 B / R.
  for (const double m : {1.0, 1.5, 2.0}) {
    const ToroidalLaw law{3.0, m, 1e-9};
    const double R = 4.2, alpha = 0.7, psi = 1.3, rho = 1e-3, h = 1.2;
    const double B = law.magnitude(R, alpha, psi, rho, h);
    EXPECT_NEAR(law.densitised_bphi(R, alpha, psi, rho, h), std::pow(psi, 4) * B / R, 1e-14 * std::pow(psi, 4) * B / R);
    const double varpi = psi * psi * R;
    EXPECT_NEAR(B, 3.0 * std::pow(alpha * alpha * varpi * varpi * rho * h, m) / (alpha * varpi), 1e-15);
  }
  const ToroidalLaw law{3.0, 1.0, 1e-9};
  EXPECT_EQ(law.densitised_bphi(4.0, 0.7, 1.3, 1e-9, 1.0), 0.0) << "rho <= rho_cut";
  EXPECT_NEAR(law.densitised_bphi(0.0, 0.7, 1.3, 1e-3, 1.2), 3.0 * 0.7 * std::pow(1.3, 6) * 1e-3 * 1.2, 1e-15) << "m = 1 on the axis";
}

// A star-like pressure p = p_c (1 - r^2 / R_s^2) inside R_s = 0.8, with psi = 1.
double star_pressure(const Point3& X) { return std::max(0.0, 1e-4 * (1.0 - (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]) / 0.64)); }

TEST(SeedMagneticField, PoloidalFacesAreDivergenceFreeAndFollowThePotential) {
  const PoloidalLaw law{1.0, 4e-6, 2.0};
  struct Case {
    CoordinateSystem c;
    int dim;
    Point3 lo, hi;
  };
  for (const Case cs : {Case{CoordinateSystem::cylindrical, 2, {0, -1, 0}, {1, 1, 0}},
                        Case{CoordinateSystem::spherical, 2, {0, 0, 0}, {1, kPi, 0}},
                        Case{CoordinateSystem::cartesian, 3, {0, 0, 0}, {1, 1, 1}}}) {
    StarBlock s(cs.c, cs.dim, 32, cs.lo, cs.hi);
    s.fill(2, star_pressure);
    s.fill(4, [](const Point3&) { return 1.0; });
    set_poloidal_faces(*s.block, law, s.at(2), s.faces(), 4);
    const auto F = s.faces();
    double worst = 0, r_min = 1e30, b_centre = 0;
    for_interior(*s.block, [&](int i, int j, int k) {
      double m = 0;
      const double div = hydrobase::cell_divergence(*s.block, F, i, j, k, &m);
      if (m > 0) worst = std::max(worst, std::abs(div) / m);
      const Point3 X = coords::to_cartesian(cs.c, cell_point(*s.block, i, j, k));
      const double r = std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
      if (r < r_min) r_min = r, b_centre = field_strength(*s.block, F, s.at(4), i, j, k);
    });
    EXPECT_LT(worst, 1e-13) << to_string(cs.c);
    // The field at the centre: B^z = (1/varpi) dA_phi/dvarpi = 2 (p_c - p_cut)^2, minus O(r^2).
    const double expected = 2.0 * std::pow(1e-4 - 4e-6, 2);
    EXPECT_NEAR(b_centre / expected, 1.0, 0.05) << to_string(cs.c);
  }
}

TEST(SeedMagneticField, ToroidalFieldOnPhiFacesOf2DGrids) {
  const ToroidalLaw law{3.0, 1.0, 1e-9};
  for (const auto c : {CoordinateSystem::cylindrical, CoordinateSystem::spherical}) {
    StarBlock s(c, 2, 16, {0, c == CoordinateSystem::spherical ? 0.0 : -1.0, 0}, {1, c == CoordinateSystem::spherical ? kPi : 1.0, 0});
    s.fill(0, [](const Point3& X) { return 1e-3 * std::max(0.0, 1 - (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]) / 0.64); });
    s.fill(1, [](const Point3&) { return 0.1; });
    s.fill(2, [](const Point3&) { return 1e-5; });
    s.fill(3, [](const Point3&) { return 0.8; });
    s.fill(4, [](const Point3&) { return 1.2; });
    add_toroidal_phi_faces(*s.block, law, s.star(), s.faces()[2]);
    const Block& b = *s.block;
    for_interior(b, [&](int i, int j, int k) {
      const double rho = s.at(0)(i, j, k);
      const double expected = rho > 1e-9 ? 3.0 * 0.8 * std::pow(1.2, 6) * rho * (1.1 + 1e-5 / rho) : 0.0;
      EXPECT_NEAR(s.faces()[2](i, j, k), expected, 1e-12 * std::abs(expected) + 1e-300);
      // |B| = psi^2 R B^phi: the paper's magnitude at the centroid, up to the O(h^2 / R^2) difference
      // between the face-mean radius of the orthonormal cell field and the centroid's.
      const double R = c == CoordinateSystem::cylindrical ? b.centroid(0, i) : b.centroid(0, i) * std::sin(b.centroid(1, j));
      const double B = field_strength(b, s.faces(), s.at(4), i, j, k);
      const double h = c == CoordinateSystem::cylindrical ? b.dx[0] : std::max(b.dx[0], b.centroid(0, i) * b.dx[1]);
      if (rho > 1e-9 && R > 4 * h)
        EXPECT_NEAR(B, law.magnitude(R, 0.8, 1.2, rho, 1.1 + 1e-5 / rho), 0.01 * B) << to_string(c) << " " << i << " " << j;
      EXPECT_EQ(s.faces()[0](i, j, k), 0.0);
    });
  }
}

}  // namespace
}  // namespace remnant::seed
