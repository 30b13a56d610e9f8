#include "diagnostics.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "face_fields.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::mhd_tests {

double max_face_value(Block& b, const Field& bx, const Field& by, const Field& bz) {
  const int up[3] = {direction_used(b, 0) ? 1 : 0, direction_used(b, 1) ? 1 : 0, direction_used(b, 2) ? 1 : 0};
  double m = 0;
  for (int k = 0; k < b.n[2] + up[2]; ++k)
    for (int j = 0; j < b.n[1] + up[1]; ++j)
      for (int i = 0; i < b.n[0] + up[0]; ++i) {
        if (j < b.n[1] && k < b.n[2]) m = std::max(m, std::abs(bx(i, j, k)));
        if (i < b.n[0] && k < b.n[2]) m = std::max(m, std::abs(by(i, j, k)));
        if (i < b.n[0] && j < b.n[1]) m = std::max(m, std::abs(bz(i, j, k)));
      }
  return m;
}

void cell_diagnostics(Block& b, const Field& bx, const Field& by, const Field& bz, double b_ref, double floor,
                      const Field& div_rel, const Field& b2, const Field& abs_b) {
  double dx_min = 1e300;
  for (int d = 0; d < 3; ++d)
    if (direction_used(b, d)) dx_min = std::min(dx_min, b.dx[d]);
  const int up[3] = {direction_used(b, 0) ? 1 : 0, direction_used(b, 1) ? 1 : 0, direction_used(b, 2) ? 1 : 0};
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) {
        // An unused direction stores one face: it is both the lower and the upper one.
        const double cx = 0.5 * (bx(i, j, k) + bx(i + up[0], j, k)), cy = 0.5 * (by(i, j, k) + by(i, j + up[1], k));
        const double cz = 0.5 * (bz(i, j, k) + bz(i, j, k + up[2]));
        b2(i, j, k) = 0.5 * (cx * cx + cy * cy + cz * cz);
        const double magnitude = std::sqrt(cx * cx + cy * cy + cz * cz);
        abs_b(i, j, k) = magnitude >= floor * b_ref ? magnitude : 0.0;
        div_rel(i, j, k) = b_ref > 0 ? std::abs(cell_divergence(b, bx, by, bz, i, j, k)) * dx_min / b_ref : 0.0;
      }
}

void magnetic_diagnostics(Context& ctx) {
  const int g1 = ctx.var("HydroBase::Bface1"), g2 = ctx.var("HydroBase::Bface2"), g3 = ctx.var("HydroBase::Bface3");
  const int div = ctx.var("MHDTests::divB"), b2 = ctx.var("MHDTests::b2"), abs_b = ctx.var("MHDTests::absB");
  const double floor = ctx.param<double>("MHDTests", "refine_field_floor");
  double b_ref = 0;
  for (Block* b : ctx.grid().local_blocks())
    b_ref = std::max(b_ref, max_face_value(*b, b->field(g1, 0), b->field(g2, 0), b->field(g3, 0)));
  MPI_Allreduce(MPI_IN_PLACE, &b_ref, 1, MPI_DOUBLE, MPI_MAX, ctx.grid().comm());
  for (Block* b : ctx.grid().local_blocks())
    cell_diagnostics(*b, b->field(g1, 0), b->field(g2, 0), b->field(g3, 0), b_ref, floor, b->field(div, 0), b->field(b2, 0),
                     b->field(abs_b, 0));
}

}  // namespace remnant::mhd_tests
