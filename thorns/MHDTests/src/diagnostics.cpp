#include "diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "face_fields.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::mhd_tests {

void cell_diagnostics(Block& b, const Field& bx, const Field& by, const Field& bz, const Field& div_rel, const Field& b2) {
  double dx_min = 1e300;
  for (int d = 0; d < 3; ++d)
    if (direction_used(b, d)) dx_min = std::min(dx_min, b.dx[d]);
  const bool used[3] = {direction_used(b, 0), direction_used(b, 1), direction_used(b, 2)};
  const int n0 = b.n[0], n1 = b.n[1], n2 = b.n[2];
  // max |B| over each cell's faces, then over the cells within kReach (the EMF stencil): the
  // neighbourhood whose field sets the round-off of this cell's faces.
  constexpr int kReach = 2;
  std::vector<double> face_max(static_cast<std::size_t>(n0) * n1 * n2);
  auto at = [&](int i, int j, int k) -> double& { return face_max[static_cast<std::size_t>(i + n0 * (j + n1 * k))]; };
  for (int k = 0; k < n2; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n0; ++i) {
        // An unused direction stores one face: it is both the lower and the upper one.
        const double x0 = bx(i, j, k), x1 = bx(i + (used[0] ? 1 : 0), j, k);
        const double y0 = by(i, j, k), y1 = by(i, j + (used[1] ? 1 : 0), k);
        const double z0 = bz(i, j, k), z1 = bz(i, j, k + (used[2] ? 1 : 0));
        at(i, j, k) = std::max({std::abs(x0), std::abs(x1), std::abs(y0), std::abs(y1), std::abs(z0), std::abs(z1)});
        const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1), cz = 0.5 * (z0 + z1);
        b2(i, j, k) = 0.5 * (cx * cx + cy * cy + cz * cz);
      }
  for (int k = 0; k < n2; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n0; ++i) {
        double scale = 0;
        for (int c = std::max(0, k - kReach); c <= std::min(n2 - 1, k + kReach); ++c)
          for (int r = std::max(0, j - kReach); r <= std::min(n1 - 1, j + kReach); ++r)
            for (int q = std::max(0, i - kReach); q <= std::min(n0 - 1, i + kReach); ++q) scale = std::max(scale, at(q, r, c));
        const double div = cell_divergence(b, bx, by, bz, i, j, k);
        div_rel(i, j, k) = scale > 0 ? std::abs(div) * dx_min / scale : 0.0;
      }
}

void magnetic_diagnostics(Context& ctx) {
  const int g1 = ctx.var("HydroBase::Bface1"), g2 = ctx.var("HydroBase::Bface2"), g3 = ctx.var("HydroBase::Bface3");
  const int div = ctx.var("MHDTests::divB"), b2 = ctx.var("MHDTests::b2");
  for (Block* b : ctx.grid().local_blocks())
    cell_diagnostics(*b, b->field(g1, 0), b->field(g2, 0), b->field(g3, 0), b->field(div, 0), b->field(b2, 0));
}

}  // namespace remnant::mhd_tests
