#include "time_step.hpp"

#include <algorithm>
#include <cmath>

#include "GRMHD/valencia.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {

double block_inverse_dt(const Groups& g, Block& b) {
  Field prim[Prim::ncomp], met[Metric::ncomp];
  for (int c = 0; c < Prim::ncomp; ++c) prim[c] = b.field(g.prim, c);
  for (int c = 0; c < Metric::ncomp; ++c) met[c] = b.field(g.metric, c);
  const bool cartesian = b.coordinates == CoordinateSystem::cartesian;
  std::array<double, 3> idx{0, 0, 0}, fd{1, 1, 1};
  for (int d = 0; d < 3; ++d)
    if (direction_used(b, d)) idx[d] = 1.0 / b.dx[d];
  double inv = 0;
  const PolarTrig trig(b);
  for_interior(b, [&](int i, int j, int k) {
    const std::ptrdiff_t o = i + j * prim[0].sj + k * prim[0].sk;
    if (!cartesian) fd = coords::metric_diagonal(b.coordinates, cell_point(b, i, j, k), trig.sin_centre(j));
    const PointMetric pm = point_metric(met[Metric::idx::psi].origin[o], met[Metric::idx::alpha].origin[o],
                                        {met[Metric::idx::beta].origin[o], met[Metric::idx::beta2].origin[o], met[Metric::idx::beta3].origin[o]}, fd);
    FluidState s;
    for (int c = 0; c < 3; ++c) {
      s.v[c] = prim[Prim::idx::vel + c].origin[o];
      s.v_dn[c] = pm.g_dn[c] * s.v[c];
    }
    s.v2 = s.v[0] * s.v_dn[0] + s.v[1] * s.v_dn[1] + s.v[2] * s.v_dn[2];
    s.cs2 = std::clamp(prim[Prim::idx::cs2].origin[o], 0.0, 1.0);
    for (int d = 0; d < 3; ++d) {
      if (idx[d] == 0) continue;
      double lm, lp;
      characteristic_speeds(d, s, pm, lm, lp);
      inv = std::max(inv, std::max(std::abs(lm), std::abs(lp)) * idx[d]);
    }
  });
  return inv;
}

}  // namespace remnant::grmhd
