#include "HydroBase/outflow_boundary.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include "remnant/coordinates.hpp"
#include "remnant/error.hpp"
#include "remnant/vars/HydroBase.hpp"

namespace remnant::hydrobase {

using Prim = vars::HydroBase::prim;

void no_inflow_face(Block& b, int prim, const PrimVelocity& c, int d, bool upper) {
  const auto ud = static_cast<std::size_t>(d);
  Field vel[3] = {b.field(prim, c.vel[0]), b.field(prim, c.vel[1]), b.field(prim, c.vel[2])};
  Field W = b.field(prim, c.lorentz);
  // The ghosts hold copies of the layer `source` (zero gradient), whose velocity and W are
  // consistent with the metric there: W^-2 = 1 - psi^4 sum_i f_ii (v^i)^2. Removing v^d leaves
  // W'^-2 = W^-2 + (1 - W^-2) f_dd (v^d)^2 / sum_i f_ii (v^i)^2, with f at the source's
  // coordinate along d: psi cancels, so the metric's ghosts need not be valid.
  const int source = upper ? b.n[ud] - 1 : 0;
  int lo[3], hi[3];
  for (std::size_t e = 0; e < 3; ++e) lo[e] = -b.ng[e], hi[e] = b.n[e] + b.ng[e];
  if (upper) lo[ud] = b.n[ud];
  else hi[ud] = 0;
  const double sign = upper ? -1.0 : 1.0;  // v^d * sign > 0: pointing into the domain
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) {
        const double vn = vel[d](i, j, k);
        if (!(vn * sign > 0)) continue;
        int idx[3] = {i, j, k};
        idx[ud] = source;
        const Point3 x = {b.centroid(0, idx[0]), b.centroid(1, idx[1]), b.centroid(2, idx[2])};
        const Point3 f = coords::metric_diagonal(b.coordinates, x);
        double v2 = 0;
        for (std::size_t e = 0; e < 3; ++e) v2 += f[e] * vel[e](i, j, k) * vel[e](i, j, k);
        const double inv_w2 = 1.0 / (W(i, j, k) * W(i, j, k));
        const double inv_w2_new = inv_w2 + (1.0 - inv_w2) * (f[ud] * vn * vn / v2);
        vel[d](i, j, k) = 0.0;
        W(i, j, k) = inv_w2_new < 1.0 ? 1.0 / std::sqrt(inv_w2_new) : 1.0;
      }
}

void register_outflow_boundary(Context& ctx) {
  const int prim = Prim::id(ctx);
  const VariableGroupSpec& spec = ctx.vars().group(prim);
  PrimVelocity c;
  for (int comp = 0; comp < spec.ncomp(); ++comp) {
    const ComponentSpec& cs = spec.components[static_cast<std::size_t>(comp)];
    if (cs.kind == TensorKind::vector && cs.indices[0] >= 0) c.vel[cs.indices[0]] = comp;
  }
  c.lorentz = Prim::idx::W;
  for (int e = 0; e < 3; ++e)
    if (c.vel[e] < 0) throw RunError("HydroBase: " + spec.full_name() + " declares no vector (the velocity)");
  // Grid-basis components: the normal of a face of direction d is the component d. A group in
  // Cartesian components would need a projection on the curvilinear normal.
  if (spec.cartesian_basis && ctx.grid().coordinates() != CoordinateSystem::cartesian)
    throw RunError("HydroBase: no_inflow needs " + spec.full_name() + " in grid-basis components");
  ctx.grid().add_outflow_condition(prim, [prim, c](Block& b, int d, bool upper) { no_inflow_face(b, prim, c, d, upper); });
}

}  // namespace remnant::hydrobase
