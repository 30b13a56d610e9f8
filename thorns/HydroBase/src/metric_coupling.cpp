// What HydroBase gives a metric solver: the densitised sources of the xCFC equations in
// Spacetime::matter_sources, and the conserved variables of the primitives with the current psi
// (initial data given as primitives).
#include <cmath>

#include "Con2Prim/prim_to_cons.hpp"
#include "remnant/cell_geometry.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/sweeps.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::hydrobase {
namespace {

using Prim = vars::HydroBase::prim;
using Cons = vars::HydroBase::cons;
using Metric = vars::Spacetime::metric;
using Sources = vars::Spacetime::matter_sources;

con2prim::Metric3 cell_metric(const Block& b, double psi, int i, int j, int k) {
  const Point3 f = coords::metric_diagonal(b.coordinates, cell_point(b, i, j, k));
  const double p4 = psi * psi * psi * psi, a = p4 * f[0], c = p4 * f[1], d = p4 * f[2];
  return con2prim::Metric3::from_lower_and_inverse({a, 0, 0, c, 0, d}, {1 / a, 0, 0, 1 / c, 0, 1 / d}, a * c * d);
}

con2prim::Vec3 cell_field(const std::array<Field, 3>& bvec, int i, int j, int k) {
  return {bvec[0](i, j, k), bvec[1](i, j, k), bvec[2](i, j, k)};
}

// b^2 of the cell from its primitives and Bvec.
double b2(const Block& b, const Prim& prim, const std::array<Field, 3>& bvec, double psi, int i, int j, int k) {
  con2prim::Primitives p;
  for (int d = 0; d < 3; ++d) p.v[d] = prim.vel(d, i, j, k);
  p.W = prim.W(i, j, k);
  p.B = cell_field(bvec, i, j, k);
  return con2prim::b_squared(p, cell_metric(b, psi, i, j, k));
}

void store(const Prim& prim, const Cons& cons, int i, int j, int k, const con2prim::Primitives& p,
           const con2prim::Conserved& c, double psi6) {
  prim.rho(i, j, k) = p.rho;
  for (int d = 0; d < 3; ++d) prim.vel(d, i, j, k) = p.v[d];
  prim.eps(i, j, k) = p.eps;
  prim.press(i, j, k) = p.press;
  prim.temperature(i, j, k) = p.T;
  prim.Ye(i, j, k) = p.ye;
  prim.W(i, j, k) = p.W;
  prim.cs2(i, j, k) = p.cs2;
  cons.D(i, j, k) = psi6 * c.D;
  for (int d = 0; d < 3; ++d) cons.S(d, i, j, k) = psi6 * c.S[d];
  cons.tau(i, j, k) = psi6 * c.tau;
  cons.DYe(i, j, k) = psi6 * c.DYe;
}

}  // namespace

void fill_matter_sources(Context& ctx) {
  const int bvec_id = FieldGroups::of(ctx).bvec;
  const bool magnetic = bvec_id >= 0;
  for (Block* b : ctx.grid().local_blocks()) {
    std::array<Field, 3> bvec{};
    if (magnetic)
      for (int d = 0; d < 3; ++d) bvec[d] = b->field(bvec_id, d);
    const Prim prim(ctx, *b);
    const Cons cons(ctx, *b);
    const Metric metric(ctx, *b);
    const Sources src(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const double p = metric.psi(i, j, k), p2 = p * p;
      src.E(i, j, k) = cons.D(i, j, k) + cons.tau(i, j, k);
      double sv = 0;
      for (int d = 0; d < 3; ++d) {
        src.S(d, i, j, k) = cons.S(d, i, j, k);
        sv += cons.S(d, i, j, k) * prim.vel(d, i, j, k);
      }
      // S~ = psi^6 S = S^_i v^i + 3 psi^6 p (S^_i the densitised momentum); with a field
      // S^j_j = S_i v^i + 3 p + b^2 / 2 (GRMHD/sources_mhd.hpp).
      if (magnetic) {
        const double bs = b2(*b, prim, bvec, p, i, j, k);
        src.S_trace(i, j, k) = sv + p2 * p2 * p2 * (3 * prim.press(i, j, k) + 0.5 * bs);
      } else {
        src.S_trace(i, j, k) = sv + 3 * p2 * p2 * p2 * prim.press(i, j, k);
      }
    });
  }
}

void conserved_from_primitives(Context& ctx) {
  const int bvec_id = FieldGroups::of(ctx).bvec;
  for (Block* b : ctx.grid().local_blocks()) {
    std::array<Field, 3> bvec{};
    if (bvec_id >= 0)
      for (int d = 0; d < 3; ++d) bvec[d] = b->field(bvec_id, d);
    const Prim prim(ctx, *b);
    const Cons cons(ctx, *b);
    const Metric metric(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const double p = metric.psi(i, j, k), p2 = p * p, psi6 = p2 * p2 * p2;
      const con2prim::Metric3 m = cell_metric(*b, p, i, j, k);
      con2prim::Primitives pr;
      pr.rho = prim.rho(i, j, k);
      for (int d = 0; d < 3; ++d) pr.v[d] = prim.vel(d, i, j, k);
      pr.eps = prim.eps(i, j, k);
      pr.press = prim.press(i, j, k);
      pr.T = prim.temperature(i, j, k);
      pr.ye = prim.Ye(i, j, k);
      pr.cs2 = prim.cs2(i, j, k);
      pr.W = 1.0 / std::sqrt(1.0 - m.norm2_up(pr.v));
      if (bvec_id >= 0) pr.B = cell_field(bvec, i, j, k);
      store(prim, cons, i, j, k, pr, con2prim::prim_to_cons(pr, m), psi6);
    });
  }
}

}  // namespace remnant::hydrobase
