// The paper (after Papenfort et al. 2021): the companion's potential changes psi inside each star,
// and with it the rest mass psi^6 W rho of fixed primitives; the stars' densities are rescaled by a
// constant so that their rest mass stays that of the isolated stars. One constant for both stars
// (they are identical and placed symmetrically). The integrals are grid reductions (the same bits
// on any rank count).
#include "rest_mass.hpp"

#include <cmath>
#include <cstdio>

#include "HydroBase/sweeps.hpp"
#include "model.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/vars/HeadOn.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::headon {

void fix_rest_mass(Context& ctx) {
  using Iso = vars::HeadOn::isolated;
  using Prim = vars::HydroBase::prim;
  using Metric = vars::Spacetime::metric;
  const Model& m = model(ctx);
  for (Block* b : ctx.grid().local_blocks()) {
    const Iso iso(ctx, *b);
    const Prim prim(ctx, *b);
    const Metric metric(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const double psi = metric.psi(i, j, k), psi2 = psi * psi, psi4 = psi2 * psi2;
      const Point3 f = coords::metric_diagonal(b->coordinates, cell_point(*b, i, j, k));
      double v2 = 0;
      for (int d = 0; d < 3; ++d) v2 += psi4 * f[static_cast<std::size_t>(d)] * prim.vel(d, i, j, k) * prim.vel(d, i, j, k);
      iso.mass_now(i, j, k) = psi4 * psi2 * iso.rho_iso(i, j, k) / std::sqrt(1 - v2);
    });
  }
  const int g = Iso::id(ctx);
  const double target = ctx.grid().reduce(g, Iso::idx::mass_target, ReductionKind::volume_integral);
  const double now = ctx.grid().reduce(g, Iso::idx::mass_now, ReductionKind::volume_integral);
  if (!(now > 0 && target > 0)) throw RunError("HeadOn_FixRestMass: no star matter on the grid (is it coarser than the stars?)");
  const double lambda = target / now;
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto& settings = ctx.service<con2prim::Settings>("con2prim");
  const auto& atm = ctx.service<atmosphere::Atmosphere>("atmosphere");
  const hydrobase::MatterGroups groups = hydrobase::MatterGroups::of(ctx);
  con2prim::Diagnostics diag;
  for (Block* b : ctx.grid().local_blocks()) {
    const Iso iso(ctx, *b);
    const Prim prim(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const double rho0 = iso.rho_iso(i, j, k);
      if (!(rho0 > 0)) return;
      const double rho = lambda * rho0;
      const tov::ColdState s = m.slice->at(m.slice->log_enthalpy(rho));
      prim.rho(i, j, k) = rho;
      prim.eps(i, j, k) = s.eps;
      prim.press(i, j, k) = s.press;
      prim.Ye(i, j, k) = s.ye;
    });
    hydrobase::prim_to_cons_block(eos, settings, atm, groups, *b, diag);
  }
  hydrobase::report_recovery(ctx, diag, "HeadOn_FixRestMass");
  char line[200];
  std::snprintf(line, sizeof line, "HeadOn: rest mass with the current psi %.9g, isolated stars %.9g (grid integrals): densities scaled by %.9f",
                now, target, lambda);
  ctx.info(line);
}

}  // namespace remnant::headon
