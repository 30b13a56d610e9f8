#include "face_vector.hpp"

#include <map>

#include "remnant/error.hpp"

namespace remnant::grid {

namespace {

int face_direction(Centering c) {
  switch (c) {
    case Centering::face_x: return 0;
    case Centering::face_y: return 1;
    case Centering::face_z: return 2;
    default: return -1;
  }
}

}  // namespace

std::vector<FaceVector> find_face_vectors(const VariableRegistry& vars, int dimension) {
  std::map<std::string, FaceVector> by_thorn;
  std::map<std::string, int> first_group;
  for (const VariableGroupSpec& g : vars.groups()) {
    const int d = face_direction(g.centering);
    const bool evolved = g.role == VariableRole::evolved;
    if (evolved && g.centering == Centering::vertex)
      throw InputError(g.where, "evolved group '" + g.full_name() + "' is vertex-centred; the Grid evolves cell-, "
                                    "face- and edge-centred groups only");
    if (g.prolongation != "divergence_preserving") {
      if (evolved && d >= 0 && d < dimension)
        throw InputError(g.where, "evolved face-centred group '" + g.full_name() +
                                      "' needs 'prolongation: divergence_preserving' (the Grid prolongs evolved "
                                      "face groups only as face-normal vectors, one group per direction)");
      continue;
    }
    if (d < 0)
      throw InputError(g.where, "group '" + g.full_name() + "' is " + to_string(g.centering) +
                                    "-centred; prolongation divergence_preserving needs face_x, face_y or face_z");
    FaceVector& v = by_thorn[g.thorn];
    v.thorn = g.thorn;
    if (!first_group.count(g.thorn)) first_group[g.thorn] = g.id;
    if (d >= dimension) continue;  // a direction the grid does not use: cell-like, prolonged as cells
    if (v.group[static_cast<std::size_t>(d)] >= 0)
      throw InputError(g.where, "thorn " + g.thorn + " declares two divergence-preserving " + to_string(g.centering) +
                                    " groups ('" + vars.group(v.group[static_cast<std::size_t>(d)]).name + "' and '" +
                                    g.name + "'); one face-normal vector per thorn has one group per direction");
    v.group[static_cast<std::size_t>(d)] = g.id;
    if (v.ncomp == 0) v.ncomp = g.ncomp();
    if (v.ncomp != g.ncomp())
      throw InputError(g.where, "divergence-preserving group '" + g.full_name() + "' has " +
                                    std::to_string(g.ncomp()) + " components, its partners " +
                                    std::to_string(v.ncomp) + "; all directions need the same components");
  }
  std::vector<FaceVector> out;
  for (auto& [thorn, v] : by_thorn) {
    for (int d = 0; d < dimension; ++d)
      if (v.group[static_cast<std::size_t>(d)] < 0) {
        const auto& g = vars.group(first_group[thorn]);
        static const char* names[3] = {"face_x", "face_y", "face_z"};
        throw InputError(g.where, "thorn " + thorn + " declares divergence-preserving face groups but none with "
                                      "centering " + names[d] + "; a " + std::to_string(dimension) +
                                      "D grid needs one per direction");
      }
    out.push_back(v);
  }
  return out;
}

std::vector<int> face_vector_membership(const std::vector<FaceVector>& vectors, int ngroups) {
  std::vector<int> m(static_cast<std::size_t>(ngroups), -1);
  for (std::size_t i = 0; i < vectors.size(); ++i)
    for (int g : vectors[i].group)
      if (g >= 0) m[static_cast<std::size_t>(g)] = static_cast<int>(i);
  return m;
}

}  // namespace remnant::grid
