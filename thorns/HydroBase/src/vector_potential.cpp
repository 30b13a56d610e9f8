// Face fields as circulations of a vector potential (see HydroBase/vector_potential.hpp).
#include "HydroBase/vector_potential.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "remnant/cell_geometry.hpp"

namespace remnant::hydrobase {

namespace {

constexpr double kPi = std::numbers::pi;

bool on_polar_axis(double theta) { return theta == 0.0 || std::abs(theta - kPi) < 1e-12; }

// The line integral of A_a along the edge along a whose other coordinates are those of x.
double edge_integral(const Block& b, const CovariantPotential& A, int a, int cell, Point3 x, bool used_a,
                     const std::vector<double>& nodes, const std::vector<double>& weights) {
  const auto ua = static_cast<std::size_t>(a);
  const CoordinateSystem c = b.coordinates;
  // x[a] is the integration variable, not yet set: only the edge's fixed coordinates say whether
  // it lies on the axis (an R or theta edge crosses it, and keeps its phi).
  if (c == CoordinateSystem::cylindrical) {
    const bool axis = a != 0 && x[0] == 0.0;
    if (axis && a == 2) return 0.0;  // a circle of radius 0
    if (axis) x[2] = 0.0;            // along the axis: one value whatever phi
  } else if (c == CoordinateSystem::spherical) {
    if (x[0] == 0.0 && a != 0) return 0.0;  // the origin
    const bool axis = a != 1 && on_polar_axis(x[1]);
    if (axis && a == 2) return 0.0;
    if (axis) x[2] = 0.0;
  }
  if (!used_a && !coords::is_angle(c, a)) {  // unit weight of an unused non-angular direction
    x[ua] = b.x(a, 0);
    return A(x)[ua];
  }
  return gauss_line_integral(A, x, a, b.face_coordinate(a, cell), b.face_coordinate(a, cell + 1), nodes, weights);
}

}  // namespace

double gauss_line_integral(const CovariantPotential& A, Point3 x, int k, double lo, double hi,
                           const std::vector<double>& nodes, const std::vector<double>& weights) {
  const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  double s = 0.0;
  for (std::size_t q = 0; q < nodes.size(); ++q) {
    x[k] = mid + half * nodes[q];
    s += weights[q] * A(x)[k];
  }
  return s * half;
}

void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  if (n < 1 || n > 16)
    throw std::invalid_argument("gauss_legendre: " + std::to_string(n) + " points; allowed 1 to 16");
  nodes.assign(static_cast<std::size_t>(n), 0.0);
  weights.assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    // Newton on P_n from the Chebyshev-like first guess.
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    nodes[static_cast<std::size_t>(i)] = x;
    weights[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

CovariantPotential covariant_from_phi_component(CoordinateSystem c, std::function<double(const Point3& x)> a_phi) {
  if (c == CoordinateSystem::cartesian)
    return [f = std::move(a_phi)](const Point3& x) -> std::array<double, 3> {
      const double w2 = x[0] * x[0] + x[1] * x[1];
      if (w2 == 0.0) return {0.0, 0.0, 0.0};
      const double a = f(x) / w2;
      return {-x[1] * a, x[0] * a, 0.0};
    };
  return [f = std::move(a_phi)](const Point3& x) -> std::array<double, 3> { return {0.0, 0.0, f(x)}; };
}

double face_orthonormal_area(const Block& b, int d, int i, int j, int k) {
  const int idx[3] = {i, j, k};
  // Coordinate length of the face along e (the unit/full-range conventions of unused directions).
  auto length = [&](int e) {
    const auto ue = static_cast<std::size_t>(e);
    if (direction_used(b, e)) return b.face_coordinate(e, idx[e] + 1) - b.face_coordinate(e, idx[e]);
    return coords::is_angle(b.coordinates, e) ? b.dx[ue] : 1.0;
  };
  auto half_square_difference = [&](int e) {  // integral of x dx over the cell along e
    const double lo = b.face_coordinate(e, idx[e]), hi = b.face_coordinate(e, idx[e] + 1);
    return 0.5 * (hi - lo) * (hi + lo);
  };
  if (b.coordinates == CoordinateSystem::spherical && d == 1)  // sqrt(f / f_thth) = r sin(theta)
    return half_square_difference(0) * b.face_factor(1, j) * length(2);
  if (b.coordinates == CoordinateSystem::spherical && d == 2)  // r
    return half_square_difference(0) * length(1);
  if (b.coordinates == CoordinateSystem::cylindrical && d == 2)  // 1
    return length(0) * length(1);
  return b.face_area(d, i, j, k);  // f_dd = 1
}

Point3 cell_orthonormal_densitised_field(const Block& b, const std::array<Field, 3>& faces, int i, int j, int k) {
  Point3 B{};
  for (int d = 0; d < 3; ++d) {
    const Field& F = faces[static_cast<std::size_t>(d)];
    const bool used = direction_used(b, d);
    const int ip = i + (d == 0 && used), jp = j + (d == 1 && used), kp = k + (d == 2 && used);
    double sum = 0.0;
    int count = 0;
    for (const auto& p : {std::array<int, 3>{i, j, k}, std::array<int, 3>{ip, jp, kp}}) {
      const double phys = face_orthonormal_area(b, d, p[0], p[1], p[2]);
      if (phys > 0.0) sum += F(p[0], p[1], p[2]) * b.face_area(d, p[0], p[1], p[2]) / phys, ++count;
    }
    B[static_cast<std::size_t>(d)] = count > 0 ? sum / count : 0.0;
  }
  return B;
}

CovariantPotential covariant_from_axisymmetric(CoordinateSystem c, AxisymmetricPotential a_phi) {
  switch (c) {
    case CoordinateSystem::cartesian:
      return [f = std::move(a_phi)](const Point3& x) -> std::array<double, 3> {
        const double w2 = x[0] * x[0] + x[1] * x[1];
        if (w2 == 0.0) return {0.0, 0.0, 0.0};
        const double a = f(std::sqrt(w2), x[2]) / w2;
        return {-x[1] * a, x[0] * a, 0.0};
      };
    case CoordinateSystem::cylindrical:
      return [f = std::move(a_phi)](const Point3& x) -> std::array<double, 3> {
        return {0.0, 0.0, f(std::abs(x[0]), x[1])};
      };
    case CoordinateSystem::spherical:
      return [f = std::move(a_phi)](const Point3& x) -> std::array<double, 3> {
        return {0.0, 0.0, f(std::abs(x[0] * std::sin(x[1])), x[0] * std::cos(x[1]))};
      };
  }
  throw std::invalid_argument("covariant_from_axisymmetric: unknown coordinate system");
}

EdgeIntegrals::EdgeIntegrals(const Block& b, const CovariantPotential& A, int quadrature_points) {
  std::vector<double> nodes, weights;
  gauss_legendre(quadrature_points, nodes, weights);
  orientation_ = b.coordinates == CoordinateSystem::cylindrical ? -1.0 : 1.0;
  for (int d = 0; d < 3; ++d) used_[static_cast<std::size_t>(d)] = direction_used(b, d);
  for (int a = 0; a < 3; ++a) {
    auto& e = extent_[static_cast<std::size_t>(a)];
    for (int d = 0; d < 3; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      e[ud] = d == a ? b.n[ud] : (used_[ud] ? b.n[ud] + 1 : 1);
    }
    auto& v = value_[static_cast<std::size_t>(a)];
    v.resize(static_cast<std::size_t>(e[0]) * static_cast<std::size_t>(e[1]) * static_cast<std::size_t>(e[2]));
    std::size_t p = 0;
    for (int k = 0; k < e[2]; ++k)
      for (int j = 0; j < e[1]; ++j)
        for (int i = 0; i < e[0]; ++i, ++p) {
          const int idx[3] = {i, j, k};
          Point3 x{};
          for (int d = 0; d < 3; ++d)
            if (d != a) x[static_cast<std::size_t>(d)] = b.face_coordinate(d, idx[d]);
          v[p] = edge_integral(b, A, a, idx[a], x, used_[static_cast<std::size_t>(a)], nodes, weights);
        }
  }
}

double EdgeIntegrals::face_flux(int d, int i, int j, int k) const {
  const int a = (d + 1) % 3, c = (d + 2) % 3;
  int pa[3] = {i, j, k}, pc[3] = {i, j, k};
  // In an unused direction the "upper" edge is the same stored edge: its terms cancel exactly.
  if (used_[static_cast<std::size_t>(a)]) pa[a] += 1;
  if (used_[static_cast<std::size_t>(c)]) pc[c] += 1;
  // Paired so that the two copies of an unused direction's edge cancel exactly.
  const double circulation =
      ((*this)(a, i, j, k) - (*this)(a, pc[0], pc[1], pc[2])) + ((*this)(c, pa[0], pa[1], pa[2]) - (*this)(c, i, j, k));
  return orientation_ * circulation;
}

void set_faces_from_edges(const Block& b, const EdgeIntegrals& edges, const std::array<Field, 3>& faces) {
  for (int d = 0; d < 3; ++d) {
    const Field& F = faces[static_cast<std::size_t>(d)];
    if (F.origin == nullptr) continue;
    int top[3];
    for (int e = 0; e < 3; ++e) top[e] = b.n[static_cast<std::size_t>(e)] + (e == d && direction_used(b, d) ? 1 : 0);
    for (int k = 0; k < top[2]; ++k)
      for (int j = 0; j < top[1]; ++j)
        for (int i = 0; i < top[0]; ++i) {
          const double area = b.face_area(d, i, j, k);
          F(i, j, k) = area > 0.0 ? edges.face_flux(d, i, j, k) / area : 0.0;
        }
  }
}

double cell_divergence(const Block& b, const std::array<Field, 3>& faces, int i, int j, int k, double* magnitude) {
  double sum = 0.0, mag = 0.0;
  for (int d = 0; d < 3; ++d) {
    if (!direction_used(b, d)) continue;  // one stored face: its two sides cancel
    const Field& F = faces[static_cast<std::size_t>(d)];
    const int ip = i + (d == 0), jp = j + (d == 1), kp = k + (d == 2);
    const double up = b.face_area(d, ip, jp, kp) * F(ip, jp, kp), lo = b.face_area(d, i, j, k) * F(i, j, k);
    sum += up - lo;
    mag += std::abs(up) + std::abs(lo);
  }
  const double volume = b.cell_volume(i, j, k);
  if (magnitude) *magnitude = mag / volume;
  return sum / volume;
}

}  // namespace remnant::hydrobase
