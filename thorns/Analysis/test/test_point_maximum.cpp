// rho_max_point (include/Analysis/point_maximum.hpp) on a Gaussian peak sampled as EXACT cell
// averages, in 3D Cartesian cells (an octant: the peak on the corner of three reflection planes) and
// in 2D cylindrical (R, z) cells (the peak on the axis and the equator, R-weighted averages):
// - the raw cell-average maxima of the two geometries differ at O(dx^2) (the axis cell's <R^2> =
//   dx^2/2 against the corner cell's <x^2 + y^2> = 2 dx^2/3);
// - the point values both converge to the true peak at fourth order there (the fit is exact for the
//   quadratic part, the quartic terms remain), so they agree far better than the raw maxima; with
//   the wrong volume weight (uniform instead of R) the cylindrical one would converge at second order;
// - a peak off the symmetry planes (interior and one-sided stencils): second order or better, and
//   closer to the peak than the raw maximum from 8 cells per Gaussian width s on.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "Analysis/point_maximum.hpp"

namespace {

using namespace remnant::analysis;

constexpr double s = 3.0;  // Gaussian width: rho = exp(-|x - c|^2 / s^2), peak 1

// Exact average of exp(-(x - c)^2 / s^2) over [lo, hi].
double average_1d(double lo, double hi, double c) {
  return 0.5 * s * std::sqrt(std::numbers::pi) * (std::erf((hi - c) / s) - std::erf((lo - c) / s)) / (hi - lo);
}
// Exact R-weighted average of exp(-R^2 / s^2) over [lo, hi] (a peak on the axis).
double average_radial(double lo, double hi) {
  return 0.5 * s * s * (std::exp(-lo * lo / (s * s)) - std::exp(-hi * hi / (s * s))) / (0.5 * (hi * hi - lo * lo));
}

struct Result {
  double raw, point;
};

std::vector<double> faces(double dx, int n) {
  std::vector<double> f(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) f[static_cast<std::size_t>(i)] = i * dx;
  return f;
}

// The largest cell average on an n^dim block of cells of size dx from 0, and the point value there.
template <class Average>
Result maximum_and_point(std::span<const CellLine> lines, int n, Average&& average) {
  const int nz = lines.size() == 3 ? n : 1;
  const std::array<int, 3> m{n, n, nz};
  std::array<int, 3> best{0, 0, 0};
  for (int k = 0; k < m[2]; ++k)
    for (int j = 0; j < m[1]; ++j)
      for (int i = 0; i < m[0]; ++i)
        if (average(i, j, k) > average(best[0], best[1], best[2])) best = {i, j, k};
  return {average(best[0], best[1], best[2]), point_maximum_at(lines, best, average)};
}

// The peak at the origin of a 3D octant (c = 0) or of the 2D cylindrical quadrant.
Result octant(double dx, const std::array<double, 3>& c, bool symmetric) {
  const int n = 8;
  const auto f = faces(dx, n);
  const std::array<CellLine, 3> lines{CellLine{CellWeight::uniform, f, symmetric}, CellLine{CellWeight::uniform, f, symmetric},
                                      CellLine{CellWeight::uniform, f, symmetric}};
  auto avg = [&](int i, int j, int k) {
    const auto I = static_cast<std::size_t>(i), J = static_cast<std::size_t>(j), K = static_cast<std::size_t>(k);
    return average_1d(f[I], f[I + 1], c[0]) * average_1d(f[J], f[J + 1], c[1]) * average_1d(f[K], f[K + 1], c[2]);
  };
  return maximum_and_point(lines, n, avg);
}

Result cylinder(double dx, double zc, bool symmetric, CellWeight radial_weight = CellWeight::radial) {
  const int n = 8;
  const auto f = faces(dx, n);
  const std::array<CellLine, 2> lines{CellLine{radial_weight, f, true}, CellLine{CellWeight::uniform, f, symmetric}};
  auto avg = [&](int i, int j, int) {
    const auto I = static_cast<std::size_t>(i), J = static_cast<std::size_t>(j);
    return average_radial(f[I], f[I + 1]) * average_1d(f[J], f[J + 1], zc);
  };
  return maximum_and_point(lines, n, avg);
}

TEST(PointMaximum, CellAveragesOfTheWeights) {
  const CellAverages u = cell_averages(CellWeight::uniform, 1, 3), r = cell_averages(CellWeight::radial, 0, 2);
  EXPECT_DOUBLE_EQ(u.x, 2);
  EXPECT_DOUBLE_EQ(u.x2, 13.0 / 3);
  EXPECT_DOUBLE_EQ(r.x, 4.0 / 3);  // int R^2 / int R over [0, 2]
  EXPECT_DOUBLE_EQ(r.x2, 2);       // dx^2 / 2
  const CellAverages mirror = cell_averages(CellWeight::radial, -2, 0);
  EXPECT_DOUBLE_EQ(mirror.x, -4.0 / 3);
  EXPECT_DOUBLE_EQ(mirror.x2, 2);
}

TEST(PointMaximum, CartesianOctantAndCylindricalAxisAgree) {
  double last3 = 0, last2 = 0;
  for (const double dx : {s / 4, s / 8, s / 16}) {
    const Result c3 = octant(dx, {0, 0, 0}, true), c2 = cylinder(dx, 0, true);
    const double e3 = std::abs(c3.point - 1), e2 = std::abs(c2.point - 1);
    std::printf("dx %.4f: raw 3D %.6f 2D %.6f (apart %.2e, dx^2/(6 s^2) %.2e); point 3D %.8f 2D %.8f (apart %.2e)\n", dx, c3.raw,
                c2.raw, c2.raw - c3.raw, dx * dx / (6 * s * s), c3.point, c2.point, std::abs(c2.point - c3.point));
    // The raw maxima differ by about the difference of <x^2 + y^2> and <R^2>, (dx^2/6) / s^2.
    EXPECT_GT(c2.raw - c3.raw, 0.8 * dx * dx / (6 * s * s));
    EXPECT_LT(c2.raw - c3.raw, 1.2 * dx * dx / (6 * s * s));
    EXPECT_LT(std::abs(c2.point - c3.point), (dx > s / 5 ? 0.15 : 0.05) * (c2.raw - c3.raw));
    EXPECT_LT(e3, 0.1 * (1 - c3.raw));
    EXPECT_LT(e2, 0.1 * (1 - c2.raw));
    if (last3 > 0) {  // fourth order: halving dx divides the error by about 16
      EXPECT_GT(last3 / e3, 12.0);
      EXPECT_GT(last2 / e2, 12.0);
    }
    last3 = e3, last2 = e2;
  }
}

TEST(PointMaximum, UniformWeightOnTheAxisWouldBeSecondOrder) {
  // The test above would fail with this weight: the axis cell's <R^2> taken as dx^2/3, not dx^2/2.
  const double e1 = std::abs(cylinder(s / 8, 0, true, CellWeight::uniform).point - 1);
  const double e2 = std::abs(cylinder(s / 16, 0, true, CellWeight::uniform).point - 1);
  EXPECT_LT(e1 / e2, 5.0);
  EXPECT_GT(e2, 10 * std::abs(cylinder(s / 16, 0, true).point - 1));
}

TEST(PointMaximum, PeakOffTheSymmetryPlanes) {
  // Interior stencils (c inside the block), one-sided ones (c in the first or last cell), and the
  // cylindrical z direction off the equator; no symmetry planes.
  const std::array<std::array<double, 3>, 3> centres{{{2.1, 2.9, 1.7}, {0.1, 2.6, 5.9}, {1.1, 0.2, 0.7}}};
  for (const auto& c : centres) {
    double last = 0;
    for (const double dx : {0.75, 0.375, 0.1875}) {
      const double scale = dx / 0.75;  // the same place relative to the cells at every dx
      const std::array<double, 3> cs{c[0] * scale, c[1] * scale, c[2] * scale};
      const Result r = octant(dx, cs, false);
      const double e = std::abs(r.point - 1);
      std::printf("centre (%.3f %.3f %.3f) dx %.4f: raw %.6f point %.8f\n", cs[0], cs[1], cs[2], dx, r.raw, r.point);
      if (dx < s / 5) EXPECT_LT(e, 0.2 * (1 - r.raw));  // one-sided extrapolation is poor at 4 cells per width
      if (last > 0) EXPECT_GT(last / e, 3.5);
      last = e;
    }
  }
  double last = 0;
  for (const double dx : {0.75, 0.375, 0.1875}) {
    const Result r = cylinder(dx, 2.3 * dx / 0.75, false);
    const double e = std::abs(r.point - 1);
    EXPECT_LT(e, 0.2 * (1 - r.raw));
    if (last > 0) EXPECT_GT(last / e, 3.5);
    last = e;
  }
}

}  // namespace
