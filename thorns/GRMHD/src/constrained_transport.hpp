#pragma once
// Constrained transport of the face fields HydroBase::Bface1..3 (psi^6 B^a averaged over the face
// with the weight sqrt f): EMFs on the edges from the face Riemann data (mhd_fluxes.hpp), the
// face right-hand sides as circulations of the EMFs, and the cell-centred field from the faces.
//
// An edge along c (with (a, b, c) cyclic) holds E_c = psi^6 (vt^b B^a - vt^a B^b) times
// (integral of sqrt f along the edge) / (its coordinate length), vt = alpha v - beta: a covariant
// component whose line integral is value * dx_c, as GridDriver::correct_edges expects. The integral of
// sqrt f = g_a g_b g_c along the edge is exactly face_factor_a * face_factor_b * volume_weight_c,
// zero on the axis and at the origin. Then d/dt (area * Bface_a) = -(circulation of E around the
// face), so the discrete divergence of every cell stays what it was to round-off.
#include "GRMHD/reconstruction.hpp"
#include "ct_faces.hpp"
#include "groups.hpp"
#include "mhd_groups.hpp"
#include "remnant/grid.hpp"

namespace remnant::grmhd {

// The EMFs on the edges of the interior (block edges included) of the used directions' edges.
// Reads the face data `ct` (ct_faces.hpp: interior faces plus one transverse ghost layer; uct_contact
// only the induction fluxes kFluxNext, kFluxPrev) and Bface1..3 (two ghost layers;
// three with edge_reconstruction = ppm).
//   uct_hll:    Del Zanna et al. 2007 (A&A 473, 11), eq. 44 form of the upwind CT of Londrillo &
//               Del Zanna 2004: E_c = -HLL_a(vt^a B^b) + HLL_b(vt^b B^a), with B^b, B^a reconstructed
//               (edge_reconstruction: MC, minmod or PPM; GRMHD::emf_reconstruction) from their faces to the edge and the speeds and velocities of the two faces
//               adjacent in each direction;
//   arithmetic: the mean of the induction fluxes of the four faces around the edge (Balsara & Spicer 1999).
// Where one transverse direction of an edge is unused, both reduce to the 1D HLL flux of the other.
//   uct_contact: Gardiner & Stone 2005 (emf_contact.hpp): the mean of the four face EMFs plus the
//               face-to-cell gradients of E upwinded by the faces' mass fluxes; needs the hydro
//               groups (prim, metric, flux_x/y/z of the same call).
void edge_emfs(EmfScheme scheme, const MhdGroups& g, const Groups& hydro, const CtFaces& ct, Block& b,
               Reconstruction edge_reconstruction = Reconstruction::mc);
// The same for uct_hll and arithmetic (which need no hydro groups).
void edge_emfs(EmfScheme scheme, const MhdGroups& g, const CtFaces& ct, Block& b,
               Reconstruction edge_reconstruction = Reconstruction::mc);

// Bface_rhs of the interior faces (block faces included) from the EMFs; zero on faces of zero area.
void face_rhs(const MhdGroups& g, Block& b);

// max over interior cells of |sum of +-area Bface| / (sum of area |Bface|) (0 where no flux): the
// discrete divergence relative to the fluxes through the cell's faces.
double relative_divergence(const MhdGroups& g, Block& b);

}  // namespace remnant::grmhd
