#pragma once
// Per-block pieces of SeedMagneticField_Initial (register.cpp glues them to the grid's variables).
#include <array>

#include "field_laws.hpp"
#include "remnant/grid.hpp"

namespace remnant::seed {

// Cell-centred inputs of one block. press needs valid ghosts (the poloidal potential interpolates
// it to the edges); the others are read at interior cells.
struct StarFields {
  Field rho, eps, press, alpha, psi;
};

// Sets the faces of the block to the poloidal field of `law` (div B = 0 to round-off by
// construction: circulations of A_phi, HydroBase/vector_potential.hpp).
void set_poloidal_faces(const Block& b, const PoloidalLaw& law, Field press, const std::array<Field, 3>& faces,
                        int quadrature_points);

// Adds psi^6 B^phi of the toroidal law on the phi faces of an axisymmetric 2D cylindrical or
// spherical block (both phi faces of a cell are the one stored face: divergence-free as it is).
void add_toroidal_phi_faces(const Block& b, const ToroidalLaw& law, const StarFields& in, Field phi_faces);

// psi^6 B^phi of the toroidal law at interior cell (i, j, k) (any coordinates).
double toroidal_densitised_bphi(const Block& b, const ToroidalLaw& law, const StarFields& in, int i, int j, int k);

// sqrt(gamma_ij B^i B^j) at an interior cell (gamma = psi^4 f) from the orthonormal cell field of
// the faces (HydroBase/vector_potential.hpp), accurate next to the origin and the axis.
double field_strength(const Block& b, const std::array<Field, 3>& faces, Field psi, int i, int j, int k);

}  // namespace remnant::seed
