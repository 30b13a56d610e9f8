#include "matter_coupling.hpp"

#include "Con2Prim/prim_to_cons.hpp"
#include "GRMHD/grid_access.hpp"
#include "Con2Prim/settings.hpp"
#include "EOS/eos.hpp"

namespace remnant::xcfc {
namespace {

using grmhd::kRho, grmhd::kVel1, grmhd::kEps, grmhd::kPress, grmhd::kTemp, grmhd::kYe, grmhd::kLorentz, grmhd::kCs2;
enum Cons : int { kD = 0, kS = 1, kTau = 4, kDYe = 5 };

con2prim::Metric3 cell_metric(const Block& b, double psi, int i, int j, int k) {
  const Point3 f = coords::metric_diagonal(b.coordinates, {b.centroid(0, i), b.centroid(1, j), b.centroid(2, k)});
  const double p4 = psi * psi * psi * psi, a = p4 * f[0], c = p4 * f[1], d = p4 * f[2];
  return con2prim::Metric3::from_lower_and_inverse({a, 0, 0, c, 0, d}, {1 / a, 0, 0, 1 / c, 0, 1 / d}, a * c * d);
}

void store(Block& b, const MatterGroups& g, int i, int j, int k, const con2prim::Primitives& p,
           const con2prim::Conserved& c, double psi6) {
  b.field(g.prim, kRho)(i, j, k) = p.rho;
  for (int d = 0; d < 3; ++d) b.field(g.prim, kVel1 + d)(i, j, k) = p.v[d];
  b.field(g.prim, kEps)(i, j, k) = p.eps;
  b.field(g.prim, kPress)(i, j, k) = p.press;
  b.field(g.prim, kTemp)(i, j, k) = p.T;
  b.field(g.prim, kYe)(i, j, k) = p.ye;
  b.field(g.prim, kLorentz)(i, j, k) = p.W;
  b.field(g.prim, kCs2)(i, j, k) = p.cs2;
  b.field(g.cons, kD)(i, j, k) = psi6 * c.D;
  for (int d = 0; d < 3; ++d) b.field(g.cons, kS + d)(i, j, k) = psi6 * c.S[d];
  b.field(g.cons, kTau)(i, j, k) = psi6 * c.tau;
  b.field(g.cons, kDYe)(i, j, k) = psi6 * c.DYe;
}

}  // namespace

MatterGroups MatterGroups::of(const Context& ctx) {
  return {ctx.var("GRMHD::cons"), ctx.var("GRMHD::prim"), ctx.var("Spacetime::metric")};
}

void conserved_from_primitives(Context& ctx, const MatterGroups& g) {
  for (Block* b : ctx.grid().local_blocks()) {
    Field psi = b->field(g.metric, 0);
    for_interior(*b, [&](int i, int j, int k) {
      const double p = psi(i, j, k), p2 = p * p, psi6 = p2 * p2 * p2;
      const con2prim::Metric3 m = cell_metric(*b, p, i, j, k);
      con2prim::Primitives pr;
      pr.rho = b->field(g.prim, kRho)(i, j, k);
      for (int d = 0; d < 3; ++d) pr.v[d] = b->field(g.prim, kVel1 + d)(i, j, k);
      pr.eps = b->field(g.prim, kEps)(i, j, k);
      pr.press = b->field(g.prim, kPress)(i, j, k);
      pr.T = b->field(g.prim, kTemp)(i, j, k);
      pr.ye = b->field(g.prim, kYe)(i, j, k);
      pr.cs2 = b->field(g.prim, kCs2)(i, j, k);
      pr.W = 1.0 / std::sqrt(1.0 - m.norm2_up(pr.v));
      store(*b, g, i, j, k, pr, con2prim::prim_to_cons(pr, m), psi6);
    });
  }
}

DensitisedStressTrace::DensitisedStressTrace(Block& b, const MatterGroups& g)
    : psi(b.field(g.metric, 0)), press(b.field(g.prim, kPress)) {
  for (int d = 0; d < 3; ++d) S[d] = b.field(g.cons, kS + d), v[d] = b.field(g.prim, kVel1 + d);
}

double DensitisedStressTrace::operator()(int i, int j, int k) const {
  const double p = psi(i, j, k), p2 = p * p;
  double sv = 0;
  for (int d = 0; d < 3; ++d) sv += S[d](i, j, k) * v[d](i, j, k);
  return sv + 3 * p2 * p2 * p2 * press(i, j, k);
}

}  // namespace remnant::xcfc
