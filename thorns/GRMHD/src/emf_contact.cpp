#include "emf_contact.hpp"

namespace remnant::grmhd {

ContactEmfFields::ContactEmfFields(const MhdGroups& mg, const Groups& g, Block& b) {
  for (int d = 0; d < 3; ++d) {
    vel[d] = b.field(g.prim, Prim::idx::vel + d);
    beta[d] = b.field(g.metric, Metric::idx::beta + d);
    bvec[d] = b.field(mg.bvec, d);
    mass_flux[d] = b.field(g.flux[d], kD);
  }
  alpha = b.field(g.metric, Metric::idx::alpha);
  psi = b.field(g.metric, Metric::idx::psi);
}

double cell_emf(const ContactEmfFields& q, int a, int b, const int* id) {
  const int i = id[0], j = id[1], k = id[2];
  const double al = q.alpha(i, j, k), p2 = q.psi(i, j, k) * q.psi(i, j, k);
  const double vta = al * q.vel[a](i, j, k) - q.beta[a](i, j, k);
  const double vtb = al * q.vel[b](i, j, k) - q.beta[b](i, j, k);
  return p2 * p2 * p2 * (vtb * q.bvec[a](i, j, k) - vta * q.bvec[b](i, j, k));
}

double contact_emf(const ContactEmfFields& q, int a, int b, const int* id, const double* ea, const double* eb) {
  double cell[2][2];  // cell[ia + 1][ib + 1]
  int c[3] = {id[0], id[1], id[2]};
  for (int ia = -1; ia <= 0; ++ia)
    for (int ib = -1; ib <= 0; ++ib) {
      c[a] = id[a] + ia;
      c[b] = id[b] + ib;
      cell[ia + 1][ib + 1] = cell_emf(q, a, b, c);
    }
  // Mass fluxes of the a-faces of rows ib (at a-index id[a]) and of the b-faces of columns ia.
  int f[3] = {id[0], id[1], id[2]};
  --f[b];
  const double ma_lo = q.mass_flux[a](f[0], f[1], f[2]);
  const double ma_hi = q.mass_flux[a](id[0], id[1], id[2]);
  f[b] = id[b];
  --f[a];
  const double mb_lo = q.mass_flux[b](f[0], f[1], f[2]);
  const double mb_hi = q.mass_flux[b](id[0], id[1], id[2]);
  // Gradients along b next to the edge, upwind along a (the a-face mass fluxes).
  const double db_hi = contact_upwind(ma_hi, cell[0][1] - eb[0], cell[1][1] - eb[1]);
  const double db_lo = contact_upwind(ma_lo, eb[0] - cell[0][0], eb[1] - cell[1][0]);
  // Gradients along a, upwind along b.
  const double da_hi = contact_upwind(mb_hi, cell[1][0] - ea[0], cell[1][1] - ea[1]);
  const double da_lo = contact_upwind(mb_lo, ea[0] - cell[0][0], ea[1] - cell[0][1]);
  return 0.25 * (ea[0] + ea[1] + eb[0] + eb[1]) + 0.25 * (db_lo - db_hi + da_lo - da_hi);
}

}  // namespace remnant::grmhd
