#pragma once
// The contact-upwind edge EMF of Gardiner & Stone 2005 (J. Comput. Phys. 205, 509, eqs. 41-45;
// GRMHD::emf = uct_contact): the mean of the four face EMFs around the edge plus the
// gradients of E between each face centre and the cell centres next to it, taken from the cell
// upwind of the face's mass flux (the contact), which restores the 1D upwind flux for plane-parallel
// flows and removes the arithmetic mean's lack of dissipation (Gardiner & Stone 2005, section 3.2).
//
// For an edge along c at the corner of cells (a-1, b-1) .. (a, b) ((a, b, c) cyclic), with face
// EMFs Ea(ib) on the a-faces of rows ib = -1, 0 and Eb(ia) on the b-faces of columns ia = -1, 0 and
// the cell-centred reference E(ia, ib) = psi^6 (vt^b B^a - vt^a B^b) (vt = alpha v - beta):
//   E = [Ea(-1) + Ea(0) + Eb(-1) + Eb(0)] / 4 + [db(lo) - db(hi) + da(lo) - da(hi)] / 4,
//   db(hi) = E(ia, 0) - Eb(ia),  db(lo) = Eb(ia) - E(ia, -1)   with ia upwind of the a-face mass flux
//   of row 0 (hi) or -1 (lo): -1 where it is positive, 0 where negative, the mean where zero;
//   da likewise with a and b exchanged. (The delta/8 * 2/delta of the paper's gradients is 1/4.)
#include "groups.hpp"
#include "mhd_groups.hpp"
#include "remnant/grid.hpp"

namespace remnant::grmhd {

// The fields one block's contact EMFs read: cell primitives, metric and Bvec (one ghost layer),
// the mass fluxes psi^6 F^d_D of the faces (flux_x/y/z, interior and one transverse ghost layer).
struct ContactEmfFields {
  Field vel[3], beta[3], alpha, psi, bvec[3], mass_flux[3];
  ContactEmfFields(const MhdGroups& mg, const Groups& g, Block& b);
};

// The value upwind of a face with this mass flux: lower (column or row -1) where it is positive,
// upper (0) where negative, their mean where it is zero.
inline double contact_upwind(double mass_flux, double lower, double upper) {
  return mass_flux > 0 ? lower : mass_flux < 0 ? upper : 0.5 * (lower + upper);
}

// psi^6 (vt^b B^a - vt^a B^b) at the centre of cell id.
double cell_emf(const ContactEmfFields& q, int a, int b, const int* id);

// E_c of the edge at the lower a- and b-faces of cell id: ea[ib + 1] = Ea(ib), eb[ia + 1] = Eb(ia).
double contact_emf(const ContactEmfFields& q, int a, int b, const int* id, const double* ea, const double* eb);

}  // namespace remnant::grmhd
