#include "cell_interpolation.hpp"

#include <algorithm>
#include <cmath>

#include "remnant/cell_geometry.hpp"

namespace remnant::seed {

CellInterpolator::CellInterpolator(const Block& b, Field f) : b_(&b), f_(f) {
  for (int d = 0; d < 3; ++d) used_[d] = direction_used(b, d);
}

double CellInterpolator::operator()(const Point3& x) const {
  const Block& b = *b_;
  int i0[3] = {0, 0, 0};
  double t[3] = {0, 0, 0};
  for (int d = 0; d < 3; ++d) {
    if (!used_[d]) continue;
    const auto ud = static_cast<std::size_t>(d);
    const double h = b.dx[ud];
    // The cell whose centre is the largest not above x, kept inside the ghost-extended block.
    int i = static_cast<int>(std::floor((x[ud] - b.face_coordinate(d, 0)) / h - 0.5));
    i = std::clamp(i, -b.ng[ud], b.n[ud] + b.ng[ud] - 2);
    const double c0 = 0.5 * (b.face_coordinate(d, i) + b.face_coordinate(d, i + 1));
    i0[d] = i;
    t[d] = std::clamp((x[ud] - c0) / h, 0.0, 1.0);
  }
  double s = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    int p[3];
    double w = 1.0;
    bool skip = false;
    for (int d = 0; d < 3; ++d) {
      const int up = (corner >> d) & 1;
      if (up && !used_[d]) skip = true;
      p[d] = i0[d] + up;
      w *= up ? t[d] : 1.0 - t[d];
    }
    if (skip || w == 0.0) continue;
    s += w * f_(p[0], p[1], p[2]);
  }
  return s;
}

}  // namespace remnant::seed
