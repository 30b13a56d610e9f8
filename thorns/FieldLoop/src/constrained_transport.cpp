#include "constrained_transport.hpp"

#include <cmath>
#include <numbers>

#include "remnant/limiters.hpp"

namespace remnant::field_loop {

namespace {
// The upwind value at the node between a (below) and b (above) along a line of face values
// am, a, b, bp with spacing h, for speed v.
double upwind(double am, double a, double b, double bp, double h, double v) {
  if (v > 0) return a + 0.5 * h * mc_slope(am, a, b, -h, 0.0, h);
  if (v < 0) return b - 0.5 * h * mc_slope(a, b, bp, -h, 0.0, h);
  return 0.5 * (a + b);
}
}  // namespace

double distance_to_centre(const Loop& loop, double t, double x, double y) {
  const double cx = loop.centre[0] + loop.velocity[0] * t, cy = loop.centre[1] + loop.velocity[1] * t;
  // The nearest periodic image of the centre.
  double dx = x - cx, dy = y - cy;
  dx -= loop.period[0] * std::round(dx / loop.period[0]);
  dy -= loop.period[1] * std::round(dy / loop.period[1]);
  return std::hypot(dx, dy);
}

double potential(const Loop& loop, double t, double x, double y) {
  const double r = distance_to_centre(loop, t, x, y);
  const double s = r * r / (loop.radius * loop.radius);
  if (s >= 1) return 0.0;
  const double w = 1 - s;
  return loop.amplitude * w * w * w * w;
}

double exact_energy(const Loop& loop) { return 4 * std::numbers::pi * loop.amplitude * loop.amplitude / 7; }

void set_initial(const Loop& loop, double t, Block& b, const Field& bx, const Field& by) {
  auto A = [&](int i, int j) { return potential(loop, t, b.face_coordinate(0, i), b.face_coordinate(1, j)); };
  for (int j = 0; j < b.n[1]; ++j)
    for (int i = 0; i <= b.n[0]; ++i) bx(i, j, 0) = (A(i, j + 1) - A(i, j)) / b.face_area(0, i, j, 0);
  for (int j = 0; j <= b.n[1]; ++j)
    for (int i = 0; i < b.n[0]; ++i) by(i, j, 0) = -(A(i + 1, j) - A(i, j)) / b.face_area(1, i, j, 0);
}

void corner_emf(const Loop& loop, Block& b, const Field& bx, const Field& by, const Field& ez) {
  const double vx = loop.velocity[0], vy = loop.velocity[1];
  for (int j = 0; j <= b.n[1]; ++j)
    for (int i = 0; i <= b.n[0]; ++i) {
      // B_x along y (faces (i, j-1) below, (i, j) above), B_y along x ((i-1, j) left, (i, j) right).
      const double bxc = upwind(bx(i, j - 2, 0), bx(i, j - 1, 0), bx(i, j, 0), bx(i, j + 1, 0), b.dx[1], vy);
      const double byc = upwind(by(i - 2, j, 0), by(i - 1, j, 0), by(i, j, 0), by(i + 1, j, 0), b.dx[0], vx);
      ez(i, j, 0) = vy * bxc - vx * byc;
    }
}

void face_rhs(Block& b, const Field& ez, const Field& bx_rhs, const Field& by_rhs) {
  // Line integrals along z: E_z times the (unit) weight of the unused direction.
  const double lz = b.volume_weight(2, 0);
  for (int j = 0; j < b.n[1]; ++j)
    for (int i = 0; i <= b.n[0]; ++i) bx_rhs(i, j, 0) = -(ez(i, j + 1, 0) - ez(i, j, 0)) * lz / b.face_area(0, i, j, 0);
  for (int j = 0; j <= b.n[1]; ++j)
    for (int i = 0; i < b.n[0]; ++i) by_rhs(i, j, 0) = (ez(i + 1, j, 0) - ez(i, j, 0)) * lz / b.face_area(1, i, j, 0);
}

void analyse(Block& b, const Field& bx, const Field& by, const Field& b2, const Field& div) {
  for (int j = 0; j < b.n[1]; ++j)
    for (int i = 0; i < b.n[0]; ++i) {
      const double x = 0.5 * (bx(i, j, 0) + bx(i + 1, j, 0)), y = 0.5 * (by(i, j, 0) + by(i, j + 1, 0));
      b2(i, j, 0) = 0.5 * (x * x + y * y);
      div(i, j, 0) = (b.face_area(0, i + 1, j, 0) * bx(i + 1, j, 0) - b.face_area(0, i, j, 0) * bx(i, j, 0) +
                      b.face_area(1, i, j + 1, 0) * by(i, j + 1, 0) - b.face_area(1, i, j, 0) * by(i, j, 0)) /
                     b.cell_volume(i, j, 0);
    }
}

}  // namespace remnant::field_loop
