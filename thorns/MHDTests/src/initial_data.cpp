#include "initial_data.hpp"

#include <cmath>

#include "diagnostics.hpp"
#include "face_fields.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "settings.hpp"

namespace remnant::mhd_tests {

void initial_primitives(Context& ctx) {
  const Settings s = settings_from(ctx);
  const double gm1 = setup_of(s.problem).gamma - 1;
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    for (int k = 0; k < b->n[2]; ++k)
      for (int j = 0; j < b->n[1]; ++j)
        for (int i = 0; i < b->n[0]; ++i) {
          const FluidState f = state_at(s, b->x(0, i), b->x(1, j));
          prim.rho(i, j, k) = f.rho;
          for (int c = 0; c < 3; ++c) prim.vel(c, i, j, k) = f.v[c];
          prim.press(i, j, k) = f.press;
          prim.eps(i, j, k) = f.press / (gm1 * f.rho);
          prim.Ye(i, j, k) = s.ye;
          prim.temperature(i, j, k) = 0;
          prim.W(i, j, k) = 1.0 / std::sqrt(1.0 - (f.v[0] * f.v[0] + f.v[1] * f.v[1] + f.v[2] * f.v[2]));
          prim.cs2(i, j, k) = 0;  // HydroBase_InitialCons recomputes it from the EOS
        }
  }
}

void initial_face_fields(Context& ctx) {
  const Settings s = settings_from(ctx);
  const int g1 = ctx.var("HydroBase::Bface1"), g2 = ctx.var("HydroBase::Bface2"), g3 = ctx.var("HydroBase::Bface3");
  for (Block* b : ctx.grid().local_blocks()) {
    const Field f1 = b->field(g1, 0), f2 = b->field(g2, 0), f3 = b->field(g3, 0);
    switch (s.problem) {
      case Problem::field_loop:
        faces_from_potential(*b, [&](double x, double y) { return field_loop_potential(s.loop, x, y); }, f1, f2, f3);
        break;
      case Problem::cylindrical_blast:
        faces_from_potential(*b, [&](double x, double y) { return uniform_x_field_potential(s.blast.B0, x, y); }, f1, f2, f3);
        break;
      case Problem::rotor:
        faces_from_potential(*b, [&](double x, double y) { return uniform_x_field_potential(s.rotor.B0, x, y); }, f1, f2, f3);
        break;
      default: {
        const RiemannProblem rp = riemann_problem(s.problem);
        const double x0 = s.discontinuity;
        faces_from_planar_field(
            *b, rp.left.B[0],
            [&](double x) {
              const FluidState& f = x < x0 ? rp.left : rp.right;
              return std::array<double, 2>{f.B[1], f.B[2]};
            },
            f1, f2, f3);
      }
    }
  }
  magnetic_diagnostics(ctx);  // absB for the initial regrid, divB/b2 of the initial data
}

}  // namespace remnant::mhd_tests
