#include "mass_budget.hpp"

#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {

DomainCells DomainCells::of(const Context& ctx) {
  DomainCells d;
  const auto& n = ctx.param<std::vector<std::int64_t>>("Grid", "ncells");
  for (int i = 0; i < 3 && i < int(n.size()); ++i) d.n[i] = n[i];
  d.dimension = int(ctx.param<std::int64_t>("Grid", "dimension"));
  return d;
}

void outflow_rhs_block(const Groups& g, const DomainCells& dom, Block& b) {
  Field out = b.field(g.budget_rhs, Budget::idx::outflow), src = b.field(g.budget_rhs, Budget::idx::source);
  for_interior(b, [&](int i, int j, int k) { out(i, j, k) = 0, src(i, j, k) = 0; });
  // The same products as the D divergence in rhs.cpp (A F / V with the 1D factors), taken only at
  // boundary faces: d(D + outflow)/dt then holds interior faces alone, which cancel in the sum.
  for (int d = 0; d < 3; ++d) {
    if (!direction_used(b, d) || !(dom.lower(b, d) || dom.upper(b, d))) continue;
    const Field F = b.field(g.flux[d], kD);
    const std::ptrdiff_t fs = d == 0 ? 1 : d == 1 ? F.sj : F.sk;
    const double* ff = b.face_factors(d);
    const double* vw = b.volume_weights(d);
    const int last = b.n[d] - 1;
    for_interior(b, [&](int i, int j, int k) {
      const int id[3] = {i, j, k};
      const double* f = F.origin + (i + j * F.sj + k * F.sk);
      if (id[d] == last && dom.upper(b, d)) out(i, j, k) += ff[last + 1] * f[fs] / vw[last];
      if (id[d] == 0 && dom.lower(b, d)) out(i, j, k) -= ff[0] * f[0] / vw[0];
    });
  }
}

}  // namespace remnant::grmhd
