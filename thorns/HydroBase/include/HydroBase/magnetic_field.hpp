#pragma once
// The magnetic field's variables as HydroBase holds them (HydroBase::magnetic_field = evolved):
// face fields Bface1..3 = psi^6 B^a averaged over the face with the weight sqrt f (the magnetic flux
// through a face is Block::face_area * value), and the cell-centred B^i in Bvec (not densitised).
#include <array>

#include "remnant/context.hpp"

namespace remnant::hydrobase {

// HydroBase::magnetic_field == evolved.
bool magnetic_field_evolved(const Context& ctx);

struct FieldGroups {
  std::array<int, 3> bface{-1, -1, -1};
  int bvec = -1, metric = -1;
  // The groups, or all -1 when the field is not evolved.
  static FieldGroups of(const Context& ctx);
};

// Bvec on the interior cells of b: B^a = (A- Bface_a(-) + A+ Bface_a(+)) / (A- + A+) / psi^6 (the
// mean of the two faces of direction a weighted by their exact areas; the plain mean where both
// areas vanish; the one face of an unused direction). In curvilinear coordinates the theta and phi
// components are then taken as the orthonormal mean over the cell divided by sqrt(f_aa) at the
// centroid (factor orthonormal_factor / sqrt f_aa, 1 + O(dx^2) away from the axis and the origin):
// the face mean of B^theta ~ 1/r weighted with r^2 is 3/(2 dr) in the first cell, 1/r_centroid is
// 4/(3 dr); with the factor a uniform field is exact there, and b^2, the sources and the
// reconstruction see a smooth field.
void cell_centred_field(const FieldGroups& g, Block& b);

// The factor that turns a flux per unit area (integral of sqrt f) of the faces normal to c into the
// mean orthonormal component sqrt(f_cc) B^c over cell id: the ratio of the area integrals of sqrt f
// and sqrt f / sqrt f_cc, i.e. int r^2 dr / int r dr (spherical theta, phi), times
// int sin theta / int 1 dtheta (spherical phi), int R dR / int dR (cylindrical phi); 1 otherwise.
double orthonormal_factor(const Block& b, int c, const int* id);

}  // namespace remnant::hydrobase
