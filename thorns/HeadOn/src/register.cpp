// HeadOn: binds the scheduled functions of thorn.yaml. HeadOn_Initial writes the superposed metric
// everywhere (ghosts included: no sync needed, ghosts across a symmetry plane get the mirror
// point's values, which the superposition has by construction) and the matter on the interior.
#include <cmath>

#include "HeadOn/binary.hpp"
#include "check_parameters.hpp"
#include "model.hpp"
#include "rest_mass.hpp"
#include "tracking.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/registrar.hpp"
#include "remnant/vars/HeadOn.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::headon {
namespace {

void initial(Context& ctx) {
  const Binary& binary = *model(ctx).binary;
  centres(ctx);  // the initial positions for the criterion of the initial regrid
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    const vars::Spacetime::metric metric(ctx, *b);
    const vars::HeadOn::isolated iso(ctx, *b);
    const CoordinateSystem cs = b->coordinates;
    for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
      for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
        for (int i = -b->ng[0]; i < b->n[0] + b->ng[0]; ++i) {
          const BinaryPoint p = binary.at(coords::to_cartesian(cs, cell_point(*b, i, j, k)));
          metric.psi(i, j, k) = p.psi;
          metric.alpha(i, j, k) = p.alpha;
          for (int c = 0; c < 3; ++c) metric.beta(c, i, j, k) = 0.0;
        }
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 x = cell_point(*b, i, j, k);
      const BinaryPoint p = binary.at(coords::to_cartesian(cs, x));
      const Point3 v = coords::vector_from_cartesian(cs, x, {0.0, 0.0, p.vz});
      prim.rho(i, j, k) = p.matter.rho;
      for (int c = 0; c < 3; ++c) prim.vel(c, i, j, k) = v[static_cast<std::size_t>(c)];
      prim.eps(i, j, k) = p.matter.eps;
      prim.press(i, j, k) = p.matter.press;
      prim.temperature(i, j, k) = 0.0;  // T follows from eps in HydroBase_InitialCons
      prim.Ye(i, j, k) = p.star >= 0 ? p.matter.ye : 0.0;
      prim.W(i, j, k) = 1.0;
      prim.cs2(i, j, k) = 0.0;
      const double rho_iso = p.star >= 0 ? p.matter.rho : 0.0, psi2 = p.psi_isolated * p.psi_isolated;
      iso.rho_iso(i, j, k) = rho_iso;
      iso.mass_target(i, j, k) = psi2 * psi2 * psi2 * rho_iso;
      iso.mass_now(i, j, k) = 0.0;
    });
  }
}

}  // namespace
}  // namespace remnant::headon

REMNANT_REGISTER_THORN(HeadOn) {
  using namespace remnant::headon;
  reg.function("HeadOn_CheckParameters", check_parameters);
  reg.function("HeadOn_RegisterCriterion", register_criterion);
  reg.function("HeadOn_Initial", initial);
  reg.function("HeadOn_FixRestMass", fix_rest_mass);
  reg.function("HeadOn_TrackStars", track_stars);
}
