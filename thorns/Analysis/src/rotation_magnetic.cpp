// Analysis_RotationMagnetic's integral and the magnetic terms of the rotation diagnostics
// (definitions in rotation_magnetic.hpp).
#include "Analysis/rotation_magnetic.hpp"

#include <cmath>

#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/vars/Analysis.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::analysis {

double magnetic_komar_stress(Context& ctx) {
  using Out = vars::Analysis::rotation_magnetic;
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    const vars::HydroBase::Bvec B(ctx, *b);
    const vars::Spacetime::metric metric(ctx, *b);
    const Out out(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 f = coords::metric_diagonal(b->coordinates, cell_point(*b, i, j, k));
      const double psi = metric.psi(i, j, k), psi4 = std::pow(psi, 4);
      double B2 = 0, v2 = 0, Bv = 0;
      for (int c = 0; c < 3; ++c) {
        const double g = psi4 * f[static_cast<std::size_t>(c)], Bc = B(c, i, j, k), vc = prim.vel(c, i, j, k);
        B2 += g * Bc * Bc, v2 += g * vc * vc, Bv += g * Bc * vc;
      }
      out.komar_em(i, j, k) = metric.alpha(i, j, k) * psi4 * psi * psi * 0.5 * (B2 * (1 - v2) + Bv * Bv);
    });
  }
  const int out = Out::id(ctx);
  ctx.check_access(out);
  return ctx.grid().reduce(out, Out::idx::komar_em, ReductionKind::volume_integral);
}

void add_magnetic_terms(RotationDiagnostics& rotation, double komar_stress, double E_mag) {
  rotation.M_komar += komar_stress;
  const double W = rotation.M_proper + rotation.T_kin + E_mag - rotation.M_komar;
  rotation.T_over_W = W != 0 ? rotation.T_kin / std::abs(W) : 0.0;
}

}  // namespace remnant::analysis
