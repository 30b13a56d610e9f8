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
// areas vanish; the one face of an unused direction).
void cell_centred_field(const FieldGroups& g, Block& b);

}  // namespace remnant::hydrobase
