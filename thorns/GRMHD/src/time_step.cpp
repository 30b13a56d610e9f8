#include "time_step.hpp"

#include <algorithm>
#include <cmath>

#include "GRMHD/valencia.hpp"
#include "GRMHD/valencia_mhd.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {

namespace {

// Mhd: the fast-magnetosonic estimate of valencia_mhd.hpp with the cell's B^i (group bvec).
template <bool Mhd>
double inverse_dt(const Groups& g, int bvec, Block& b) {
  Field prim[Prim::ncomp], met[Metric::ncomp], bf[3];
  if constexpr (Mhd)
    for (int c = 0; c < 3; ++c) bf[c] = b.field(bvec, c);
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
    double signal2 = s.cs2;
    if constexpr (Mhd) {
      s.rho = prim[Prim::idx::rho].origin[o];
      s.W = prim[Prim::idx::W].origin[o];
      s.h = 1.0 + prim[Prim::idx::eps].origin[o] + prim[Prim::idx::press].origin[o] / s.rho;
      signal2 = std::min(fast_speed2(s, magnetic_state(s, pm, bf[0].origin[o], bf[1].origin[o], bf[2].origin[o])), 1.0);
    }
    for (int d = 0; d < 3; ++d) {
      if (idx[d] == 0) continue;
      double lm, lp;
      characteristic_speeds_with(d, signal2, s, pm, lm, lp);
      inv = std::max(inv, std::max(std::abs(lm), std::abs(lp)) * idx[d]);
    }
  });
  return inv;
}

}  // namespace

double block_inverse_dt(const Groups& g, Block& b) { return inverse_dt<false>(g, -1, b); }
double block_inverse_dt_mhd(const Groups& g, int bvec, Block& b) { return inverse_dt<true>(g, bvec, b); }

}  // namespace remnant::grmhd
