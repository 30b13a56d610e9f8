#pragma once
// Rotation diagnostics of a star (Analysis::rotation = true), from the conserved variables
// (densitised by psi^6), the primitives and the metric, as volume integrals over the grid's domain
// (like the rest mass: a grid with equatorial symmetry holds half the star):
//   J        = int S~_phi dV                       (S~_phi = S~_i k^i, k = d_phi the axial Killing vector)
//   M_komar  = int [alpha (E~ + S~) - 2 beta^i S~_i] dV,  E~ = tau + D,  S~ = S~_i v^i + 3 psi^6 p
//   M_proper = int D (1 + eps) dV
//   T        = 1/2 int Omega S~_phi dV,  Omega = u^phi / u^t = alpha v^phi - beta^phi
//   |W|      = M_proper + T - M_komar,  T_over_W = T / |W|
//   Omega_c  = Omega at the cell nearest the coordinate origin (as rho_c)
//   mode_m   = |int D e^{i m phi} dV| / int D dV  (m = 1, 2; phi = atan2(y, x)) over the whole star:
//              on a 3D Cartesian grid with mirror planes x = 0 or y = 0 each cell counts with its
//              mirror images (so a symmetric star gives exactly 0 for m = 1); a perturbation
//              rho (1 + delta cos m phi) gives delta / 2. 0 on 1D and 2D (axisymmetric) grids.
// Each integral is the grid's reduction of a per-cell integrand (Analysis::rotation_integrands), so
// every value has the same bits on any rank count.
#include "remnant/context.hpp"

namespace remnant::analysis {

struct RotationDiagnostics {
  double J = 0, M_komar = 0, M_proper = 0, T_kin = 0, T_over_W = 0, omega_c = 0, mode_m1 = 0, mode_m2 = 0;
};

// Collective over the grid's ranks; every rank gets the same values.
RotationDiagnostics rotation_diagnostics(Context& ctx);

}  // namespace remnant::analysis
