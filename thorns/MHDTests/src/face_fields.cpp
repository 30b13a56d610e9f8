#include "face_fields.hpp"

#include "remnant/cell_geometry.hpp"

namespace remnant::mhd_tests {

namespace {
// Faces normal to d run from 0 to n[d] where d is used; an unused direction has one face (index 0).
int face_end(const Block& b, int d) { return b.n[d] + (direction_used(b, d) ? 1 : 0); }
}  // namespace

void faces_from_potential(Block& b, const Potential& Az, const Field& bx, const Field& by, const Field& bz) {
  const auto& n = b.n;
  for (int k = 0; k < n[2]; ++k) {
    const double lz = b.volume_weight(2, k);  // length of the z edges (1 in 2D)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < face_end(b, 0); ++i) {
        const double x = b.face_coordinate(0, i);
        const double flux = lz * (Az(x, b.face_coordinate(1, j + 1)) - Az(x, b.face_coordinate(1, j)));
        bx(i, j, k) = flux / b.face_area(0, i, j, k);
      }
    for (int j = 0; j < face_end(b, 1); ++j)
      for (int i = 0; i < n[0]; ++i) {
        const double y = b.face_coordinate(1, j);
        const double flux = -lz * (Az(b.face_coordinate(0, i + 1), y) - Az(b.face_coordinate(0, i), y));
        by(i, j, k) = flux / b.face_area(1, i, j, k);
      }
  }
  for (int k = 0; k < face_end(b, 2); ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) bz(i, j, k) = 0.0;
}

void faces_from_planar_field(Block& b, double Bx, const std::function<std::array<double, 2>(double x)>& transverse,
                             const Field& bx, const Field& by, const Field& bz) {
  const auto& n = b.n;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < face_end(b, 0); ++i) bx(i, j, k) = Bx;
  for (int i = 0; i < n[0]; ++i) {
    const std::array<double, 2> t = transverse(b.x(0, i));
    for (int k = 0; k < n[2]; ++k)
      for (int j = 0; j < face_end(b, 1); ++j) by(i, j, k) = t[0];
    for (int k = 0; k < face_end(b, 2); ++k)
      for (int j = 0; j < n[1]; ++j) bz(i, j, k) = t[1];
  }
}

double cell_divergence(const Block& b, const Field& bx, const Field& by, const Field& bz, int i, int j, int k) {
  double s = 0;
  if (direction_used(b, 0)) s += b.face_area(0, i + 1, j, k) * bx(i + 1, j, k) - b.face_area(0, i, j, k) * bx(i, j, k);
  if (direction_used(b, 1)) s += b.face_area(1, i, j + 1, k) * by(i, j + 1, k) - b.face_area(1, i, j, k) * by(i, j, k);
  if (direction_used(b, 2)) s += b.face_area(2, i, j, k + 1) * bz(i, j, k + 1) - b.face_area(2, i, j, k) * bz(i, j, k);
  return s / b.cell_volume(i, j, k);
}

}  // namespace remnant::mhd_tests
