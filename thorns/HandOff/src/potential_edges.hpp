#pragma once
// The vector potential's edge integrals on a block's frame, from the fluxes of the 3D data through
// the grid's faces (magnetic_import.hpp):
// - 2D cylindrical / spherical: 2 pi A_phi = Psi, the phi-averaged poloidal flux function, at
//   every node (marching from the axis over the z faces, or from the pole over the r faces);
// - 3D (any coordinates): the axial gauge A_g = 0 along a gauge direction g (Cartesian z,
//   cylindrical z, spherical r): on the grid's lowest g face A_q from the fluxes through its g faces
//   (marching along p from the grid's lowest p face, A_p = 0), then A_p and A_q integrated along g
//   by the fluxes through the q and p faces. Cartesian (p, q, g) = (x, y, z), cylindrical
//   (R, phi, z), spherical (theta, phi, r): phi is never marched along, so a periodic phi closes
//   (the faces at phi = 2 pi take the fluxes at phi = 0 bit for bit); edges on an axis or at the
//   origin get exactly 0 (zero-area faces carry zero flux).
// Every value depends only on the edge's global position on its level (sums in a fixed order from
// the grid's lower faces), so blocks that share an edge compute the same bits. On refined grids an
// edge on the boundary of a leaf one level finer takes the sum of the fine edges along it; across
// a periodic face of a 3D grid the leaf's edges one period away (its own plus the net flux through
// a period: a potential with net flux through the domain is periodic only up to that sum).
#include <span>
#include <vector>

#include "edge_table.hpp"
#include "face_flux.hpp"
#include "remnant/grid.hpp"

namespace remnant::handoff {

// How a level's edge tables are built for the grid.
struct EdgeBuilder {
  const FluxQuadrature& q;
  CoordinateSystem cs;
  bool phi_average;  // 2D cylindrical / spherical
  double closure;    // HandOff::flux_closure_tolerance (2D)
  std::array<double, 3> xmin{}, xmax{};
  std::array<bool, 3> periodic{};

  // The frame of the leaf `key` of blocks shaped like b (all blocks have b's cell counts).
  Frame frame(const Block& b, const BlockKey& key) const;
  EdgeTable edges(const Frame& f) const;
  // edges(f) one period further along the periodic directions (shift: -1, 0, +1 each) minus
  // edges(f): a leaf seen across a periodic face (zero on 2D grids).
  EdgeTable period_jumps(const Frame& f, const std::array<int, 3>& shift) const;
};

// Replaces the edges of b (frame fb) that lie on the boundary of a leaf one level finer by the sum
// of that leaf's edges along them (the coincident node value along an unused direction): every
// face of b on a coarse-fine interface then carries exactly the sum of the fine fluxes through it.
void match_finer_leaves(const Block& b, const Frame& fb, const EdgeBuilder& builder, std::span<const BlockKey> leaves,
                        EdgeTable& t);

}  // namespace remnant::handoff
