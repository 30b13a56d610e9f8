// Analysis's magnetic diagnostics on Blocks built here: energies of known fields, the
// poloidal/toroidal split, B_max, and divB_max at round-off for a potential field but O(1) for a
// field with one face changed.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "Analysis/magnetic_diagnostics.hpp"
#include "HydroBase/vector_potential.hpp"
#include "remnant/coordinates.hpp"

namespace remnant::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

struct FieldBlock {
  VariableRegistry vars;
  int face[3], psi, density;
  std::unique_ptr<Block> block;
  FieldBlock(CoordinateSystem c, int dim, int n, Point3 lo, Point3 hi) {
    const Centering cs[3] = {Centering::face_x, Centering::face_y, Centering::face_z};
    for (int d = 0; d < 3; ++d) face[d] = add("B" + std::to_string(d + 1), cs[d], 1);
    psi = add("psi", Centering::cell, 1);
    density = add("E", Centering::cell, 3);
    std::array<int, 3> cells{1, 1, 1}, ghosts{0, 0, 0};
    std::array<double, 3> dx{};
    for (int d = 0; d < 3; ++d) {
      const auto u = static_cast<std::size_t>(d);
      if (d >= dim) lo[u] = 0, hi[u] = (c == CoordinateSystem::spherical && d == 1) ? kPi : 2 * kPi;
      else cells[u] = n, ghosts[u] = 2;
      dx[u] = (hi[u] - lo[u]) / cells[u];
    }
    block = std::make_unique<Block>(0, 0, std::array<std::int64_t, 3>{0, 0, 0}, cells, ghosts, lo, dx, vars);
    block->set_geometry(c, lo);
  }
  int add(const std::string& name, Centering c, int ncomp) {
    VariableGroupSpec g;
    g.thorn = "Test";
    g.name = name;
    g.centering = c;
    for (int k = 0; k < ncomp; ++k) g.components.push_back(expand_tensor(TensorKind::scalar, name + std::to_string(k))[0]);
    return vars.add(std::move(g));
  }
  std::array<Field, 3> faces() { return {block->field(face[0], 0), block->field(face[1], 0), block->field(face[2], 0)}; }
  std::array<Field, 3> densities() { return {block->field(density, 0), block->field(density, 1), block->field(density, 2)}; }
  void fill_psi(double value) {
    std::fill(block->data(psi), block->data(psi) + block->size(psi), value);
  }
  // Ghost faces stay 0 (the neighbourhood maximum of divB_max only looks larger with synced ones).
  MagneticBlockMaxima pass(double floor_fraction = 0) {
    return magnetic_block_pass(*block, faces(), block->field(psi, 0), densities(),
                               floor_fraction * densitised_field_max(*block, faces()));
  }
  double integral(int comp) {
    double s = 0;
    for_interior(*block, [&](int i, int j, int k) { s += block->field(density, comp)(i, j, k) * block->cell_volume(i, j, k); });
    return s;
  }
};

TEST(MagneticDiagnostics, UniformFieldEnergyAndMaximum) {
  // B0 e_z with psi = 1.1 (psi^6 B given on the faces): E = (1/2) B^2 psi^6 V, B^2 = psi^4 B0^2.
  const double B0 = 2e-4, psi = 1.1, s6 = std::pow(psi, 6);
  for (auto c : {CoordinateSystem::cylindrical, CoordinateSystem::spherical}) {
    FieldBlock f(c, 2, 16, {0, c == CoordinateSystem::spherical ? 0.0 : -1.0, 0}, {1, c == CoordinateSystem::spherical ? kPi : 1.0, 0});
    f.fill_psi(psi);
    hydrobase::set_faces_from_potential(*f.block, hydrobase::covariant_from_axisymmetric(c, [&](double w, double) { return 0.5 * s6 * B0 * w * w; }),
                                        f.faces());
    const MagneticBlockMaxima m = f.pass();
    double volume = 0;
    for_interior(*f.block, [&](int i, int j, int k) { volume += f.block->cell_volume(i, j, k); });
    const double expected = 0.5 * psi * psi * psi * psi * B0 * B0 * s6 * volume;
    // Truncation error of |cell mean|^2 against the mean of |B|^2 (0.9 % on 16 spherical cells).
    EXPECT_NEAR(f.integral(0) / expected, 1.0, 0.02) << to_string(c);
    EXPECT_NEAR(f.integral(1), f.integral(0), 1e-12 * expected);
    EXPECT_EQ(f.integral(2), 0.0);
    EXPECT_NEAR(m.B / (psi * psi * B0), 1.0, 0.02) << to_string(c);
  }
}

TEST(MagneticDiagnostics, ToroidalPartOnCartesianGridsByTheCylindricalSplit) {
  // B = b e_phi-hat (physical) on a 3D Cartesian block, psi = 1: all energy toroidal.
  FieldBlock f(CoordinateSystem::cartesian, 3, 12, {-1, -1, -1}, {1, 1, 1});
  f.fill_psi(1.0);
  auto A = [](const Point3& x) -> std::array<double, 3> {  // A_z = -(varpi^2 / 2) e^{-z^2}: B_phi-hat = varpi e^{-z^2}
    return {0, 0, -0.5 * (x[0] * x[0] + x[1] * x[1]) * std::exp(-x[2] * x[2])};
  };
  hydrobase::set_faces_from_potential(*f.block, A, f.faces());
  f.pass();
  EXPECT_GT(f.integral(2), 0.0);
  EXPECT_LT(f.integral(1), 0.02 * f.integral(2)) << "only the z-derivative of A_z gives a poloidal part";
  EXPECT_NEAR(f.integral(1) + f.integral(2), f.integral(0), 1e-12 * f.integral(0));
}

TEST(MagneticDiagnostics, DivBMaxIsRoundOffForPotentialFieldsAndDetectsAChangedFace) {
  for (auto c : {CoordinateSystem::cartesian, CoordinateSystem::cylindrical, CoordinateSystem::spherical}) {
    const bool cart = c == CoordinateSystem::cartesian;
    FieldBlock f(c, cart ? 3 : 2, 12, {cart ? -1.0 : 0.0, cart || c == CoordinateSystem::cylindrical ? -1.0 : 0.0, -1},
                 {1, c == CoordinateSystem::spherical ? kPi : 1.0, 1});
    f.fill_psi(1.2);
    auto A = hydrobase::covariant_from_axisymmetric(c, [](double w, double z) { return w * w * std::exp(-w * w - z * z); });
    hydrobase::set_faces_from_potential(*f.block, A, f.faces());
    EXPECT_LT(f.pass().div_scaled, 1e-14) << to_string(c);
    double fmax = 0;
    for_interior(*f.block, [&](int i, int j, int k) { fmax = std::max(fmax, std::abs(f.faces()[0](i, j, k))); });
    f.faces()[0](5, 6, cart ? 6 : 0) += 0.01 * fmax;  // one face off by 1 % of the largest: a monopole pair
    EXPECT_GT(f.pass().div_scaled, 1e-3) << to_string(c);
  }
}

TEST(MagneticDiagnostics, DivBMaxMeasuresWeakFieldRegionsAgainstTheFieldsScale) {
  // A strong potential field, plus round-off-sized divergence (1e-16 of the strongest face) in a
  // cell whose own field is 1e-12 of the maximum: as behind a loop that moved on. Against the
  // local field alone that reads as O(1e-4); with the floor it is round-off. A divergence of 1e-3
  // of the strongest face there is still caught.
  FieldBlock f(CoordinateSystem::cartesian, 2, 16, {-1, -1, 0}, {1, 1, 1});
  f.fill_psi(1.0);
  hydrobase::set_faces_from_potential(*f.block, [](const Point3& x) -> std::array<double, 3> {
    const double r2 = x[0] * x[0] + x[1] * x[1];
    return {0, 0, r2 < 0.25 ? (0.25 - r2) * (0.25 - r2) : 0.0};
  }, f.faces());
  double fmax = 0;
  for_interior(*f.block, [&](int i, int j, int k) { fmax = std::max(fmax, std::abs(f.faces()[0](i, j, k))); });
  // The column of cells i = 0 lies outside the loop: a uniform weak B^y of 1e-12 fmax along it
  // (divergence-free), then one face off by 1e-16 fmax.
  for (int j = 0; j <= 16; ++j) f.faces()[1](0, j, 0) = 1e-12 * fmax;
  EXPECT_LT(f.pass().div_scaled, 1e-14);
  f.faces()[1](0, 5, 0) += 1e-16 * fmax;
  EXPECT_GT(f.pass().div_scaled, 1e-6) << "without the floor the round-off looks large";
  EXPECT_LT(f.pass(kDivBScaleFloor).div_scaled, 1e-12);
  f.faces()[1](0, 5, 0) += 1e-3 * fmax;
  EXPECT_GT(f.pass(kDivBScaleFloor).div_scaled, 1e-4);
}

}  // namespace
}  // namespace remnant::analysis
