#pragma once
// Face-normal vectors (a magnetic field stored as fluxes through cell faces): the face-centred
// groups of one thorn declared with `prolongation: divergence_preserving`, one per used
// direction (face_x, face_y, face_z), component c of each forming one vector. The Grid prolongs
// them together so that the discrete divergence (1/V) sum(+-A B) is kept (face_prolongation.hpp).
#include <array>
#include <string>
#include <vector>

#include "remnant/variables.hpp"

namespace remnant::grid {

struct FaceVector {
  std::string thorn;
  std::array<int, 3> group{-1, -1, -1};  // face_x, face_y, face_z group ids; -1 beyond dimension
  int ncomp = 0;
};

// Collects the face vectors and checks the declarations. Throws InputError (at the group's
// thorn.yaml line) for: divergence_preserving on a group that is not face-centred; a thorn whose
// divergence-preserving groups do not give exactly one group per used direction with the same
// components; an evolved face group in a used direction outside such a vector; an evolved
// vertex-centred group (evolved edge groups, e.g. a vector potential, are prolonged bilinearly).
std::vector<FaceVector> find_face_vectors(const VariableRegistry& vars, int dimension);

// Per group: the index of the face vector it belongs to in a used direction, or -1.
std::vector<int> face_vector_membership(const std::vector<FaceVector>& vectors, int ngroups);

}  // namespace remnant::grid
