#pragma once
// Face-normal magnetic fields of the problems, written so that the discrete divergence
// (1/V) sum(+-area * value) of every cell is zero to round-off:
// - from a potential A_z(x, y) through HydroBase's vector-potential library (the flux through a
//   face is the circulation of A around it; edge integrals shared by neighbouring faces);
// - for a field that varies along x only (the 1D Riemann problems): B^x uniform on the x faces,
//   B^y and B^z of the cell on its y and z faces (each cell's pair of transverse faces is equal).
// Values are flux / exact face area (the data model's convention, flat space: psi = 1).
#include <array>
#include <functional>

#include "remnant/grid.hpp"

namespace remnant::mhd_tests {

using Potential = std::function<double(double x, double y)>;

// Interior faces (block faces included) of the three face groups, Cartesian blocks.
void faces_from_potential(Block& b, const Potential& Az, const Field& bx, const Field& by, const Field& bz);

// B(x) = (Bx, By(x), Bz(x)) with Bx the same everywhere; `transverse(x)` gives {By, Bz} at x.
void faces_from_planar_field(Block& b, double Bx, const std::function<std::array<double, 2>(double x)>& transverse,
                             const Field& bx, const Field& by, const Field& bz);

// Discrete divergence of cell (i, j, k): (1/V) sum over its faces of +-area * value.
double cell_divergence(const Block& b, const Field& bx, const Field& by, const Field& bz, int i, int j, int k);

}  // namespace remnant::mhd_tests
