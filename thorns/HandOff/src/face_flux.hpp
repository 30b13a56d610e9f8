#pragma once
// Fluxes of the 3D data's densitised field Bt = sqrt(gamma) B through faces of the grid's
// coordinates: Gauss-Legendre quadratures (3 x 3 points per face) of the interpolated Bt (limited
// cubic Lagrange, as the fluid), averaged over phi on 2D grids; zero outside the data.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "HandOff/sampler.hpp"
#include "HydroBase/vector_potential.hpp"
#include "magnetic_source.hpp"
#include "remnant/coordinates.hpp"

namespace remnant::handoff {

// Fluxes of the densitised 3D field through faces of the grid's coordinates.
class FluxQuadrature {
 public:
  static constexpr double kTwoPi = 2 * std::numbers::pi;
  static constexpr int kQuadrature = 3;  // Gauss-Legendre points per face direction

  FluxQuadrature(const SourceData& src, CoordinateSystem cs, bool phi_average, int phi_param)
      : sampler_(src, densitised_field_names()), cs_(cs), phi_average_(phi_average), phi_param_(phi_param) {
    hydrobase::gauss_legendre(kQuadrature, nodes_, weights_);
  }

  // sqrt(f) Bt^d in the grid's coordinates at x (the mean over phi on 2D grids): a flux per
  // coordinate area.
  double density(Point3 x, int d) const {
    double sqrt_f = 1;
    for (int e = 0; e < 3; ++e) sqrt_f *= coords::volume_factor(cs_, e, x[static_cast<std::size_t>(e)]);
    if (sqrt_f == 0) return 0.0;
    if (!phi_average_) return sqrt_f * component(x, d);
    const double ring = cs_ == CoordinateSystem::cylindrical ? x[0] : x[0] * std::sin(x[1]);
    x[2] = 0;
    const double h = sampler_.spacing_at(coords::to_cartesian(cs_, x));
    const int n = phi_param_ > 0 ? phi_param_ : std::clamp(static_cast<int>(std::ceil(kTwoPi * std::abs(ring) / h)), 8, 4096);
    double sum = 0;
    for (int m = 0; m < n; ++m) {
      x[2] = (m + 0.5) * kTwoPi / n;
      sum += component(x, d);
    }
    return sqrt_f * sum / n;
  }

  // The flux through the face normal to d at x^d = xd spanning [lo[e], hi[e]] in the other two
  // directions; a direction with one point (phi of a 2D grid: the density is its mean) is weighed
  // by its length.
  double flux(int d, double xd, const Point3& lo, const Point3& hi) const {
    const int e1 = d == 0 ? 1 : 0, e2 = d == 2 ? 1 : 2;
    auto points = [&](int e) { return phi_average_ && e == 2 ? 1 : kQuadrature; };
    double sum = 0;
    Point3 x{};
    x[static_cast<std::size_t>(d)] = xd;
    const auto u1 = static_cast<std::size_t>(e1), u2 = static_cast<std::size_t>(e2);
    const double h1 = 0.5 * (hi[u1] - lo[u1]), h2 = 0.5 * (hi[u2] - lo[u2]);
    for (int q2 = 0; q2 < points(e2); ++q2) {
      const double t2 = points(e2) == 1 ? 0.0 : nodes_[static_cast<std::size_t>(q2)];
      const double w2 = points(e2) == 1 ? 2.0 : weights_[static_cast<std::size_t>(q2)];
      x[u2] = 0.5 * (hi[u2] + lo[u2]) + h2 * t2;
      for (int q1 = 0; q1 < points(e1); ++q1) {
        x[u1] = 0.5 * (hi[u1] + lo[u1]) + h1 * nodes_[static_cast<std::size_t>(q1)];
        sum += w2 * weights_[static_cast<std::size_t>(q1)] * density(x, d);
      }
    }
    return sum * h1 * h2;
  }

 private:
  double component(const Point3& x, int d) const {
    double Bt[3];
    if (!sampler_.sample(coords::to_cartesian(cs_, x), Bt)) return 0.0;
    return coords::vector_from_cartesian(cs_, x, {Bt[0], Bt[1], Bt[2]})[static_cast<std::size_t>(d)];
  }
  Sampler sampler_;
  CoordinateSystem cs_;
  bool phi_average_;
  int phi_param_;
  std::vector<double> nodes_, weights_;
};

}  // namespace remnant::handoff
