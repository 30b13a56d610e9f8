#pragma once
// Cartesian positions of grid points, so that ParaView/VisIt show cylindrical and spherical data
// in physical space. Grid directions: cylindrical (R, z, phi), spherical (r, theta, phi).
#include <array>

#include "remnant/grid.hpp"

namespace remnant::io {

// Number of Cartesian components a grid of this dimension maps to: 2D cylindrical (R, z) and 2D
// spherical (r, theta) are meridional planes drawn as x = R, y = z; 3D grids map to (x, y, z).
int cartesian_components(CoordinateSystem c, int dimension);

// Cartesian point of grid coordinates q (only the first `dimension` entries are used).
std::array<double, 3> to_cartesian(CoordinateSystem c, int dimension, const std::array<double, 3>& q);

}  // namespace remnant::io
