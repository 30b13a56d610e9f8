#include "HydroBase/magnetic_field.hpp"

#include "remnant/cell_geometry.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::hydrobase {

bool magnetic_field_evolved(const Context& ctx) {
  return ctx.param<std::string>("HydroBase", "magnetic_field") == "evolved";
}

FieldGroups FieldGroups::of(const Context& ctx) {
  FieldGroups g;
  if (!magnetic_field_evolved(ctx)) return g;
  for (int d = 0; d < 3; ++d) g.bface[d] = ctx.var("HydroBase::Bface" + std::to_string(d + 1));
  g.bvec = ctx.var("HydroBase::Bvec");
  g.metric = vars::Spacetime::metric::id(ctx);
  return g;
}

void cell_centred_field(const FieldGroups& g, Block& b) {
  const Field psi = b.field(g.metric, vars::Spacetime::metric::idx::psi);
  for (int a = 0; a < 3; ++a) {
    const bool used = direction_used(b, a);
    const Field bf = b.field(g.bface[a], 0);
    const Field out = b.field(g.bvec, a);
    for_interior(b, [&](int i, int j, int k) {
      const double p2 = psi(i, j, k) * psi(i, j, k), ipsi6 = 1.0 / (p2 * p2 * p2);
      if (!used) {
        out(i, j, k) = bf(i, j, k) * ipsi6;
        return;
      }
      int up[3] = {i, j, k};
      ++up[a];
      const double lo = bf(i, j, k), hi = bf(up[0], up[1], up[2]);
      const double am = b.face_area(a, i, j, k), ap = b.face_area(a, up[0], up[1], up[2]);
      const double w = am + ap;
      out(i, j, k) = (w > 0 ? (am * lo + ap * hi) / w : 0.5 * (lo + hi)) * ipsi6;
    });
  }
}

}  // namespace remnant::hydrobase
