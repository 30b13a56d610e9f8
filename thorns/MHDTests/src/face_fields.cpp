#include "face_fields.hpp"

#include "HydroBase/vector_potential.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::mhd_tests {

namespace {
// Faces normal to d run from 0 to n[d] where d is used; an unused direction has one face (index 0).
int face_end(const Block& b, int d) { return b.n[d] + (direction_used(b, d) ? 1 : 0); }
}  // namespace

void faces_from_potential(Block& b, const Potential& Az, const Field& bx, const Field& by, const Field& bz) {
  const hydrobase::CovariantPotential A = [&](const Point3& x) { return Point3{0.0, 0.0, Az(x[0], x[1])}; };
  hydrobase::set_faces_from_potential(b, A, {bx, by, bz});
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
  return hydrobase::cell_divergence(b, {bx, by, bz}, i, j, k);
}

}  // namespace remnant::mhd_tests
