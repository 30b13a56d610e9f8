#pragma once
// Declared grid variables: groups of components with a centering and a tensor type. Parities under
// reflections and (later) coordinate symmetries derive from the tensor type, never per variable.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "remnant/condition.hpp"
#include "remnant/error.hpp"

namespace remnant {

enum class Centering : std::uint8_t { cell, face_x, face_y, face_z, edge_x, edge_y, edge_z, vertex };

// 1 where the centering sits on cell faces (nodes) in that direction, 0 where at cell centres.
std::array<int, 3> staggering(Centering c);
const char* to_string(Centering c);

// vector/covector: 3 components; axial_vector: a pseudo-vector such as B (opposite reflection
// parity); tensor_uu/tensor_dd: symmetric rank-2, 6 components (11 12 13 22 23 33).
enum class TensorKind : std::uint8_t { scalar, vector, covector, axial_vector, tensor_uu, tensor_dd };
const char* to_string(TensorKind k);
int component_count(TensorKind k);

enum class VariableRole : std::uint8_t { evolved, derived, auxiliary };

struct ComponentSpec {
  std::string name;                // e.g. "u", "S1", "gamma23"
  TensorKind kind = TensorKind::scalar;
  std::array<int, 2> indices{-1, -1};  // tensor indices (0..2), -1 when absent
  // Sign of the component under the reflection x^d -> -x^d, for d = 0, 1, 2.
  std::array<int, 3> reflection_parity{1, 1, 1};
};

struct VariableGroupSpec {
  int id = -1;                     // index in the VariableRegistry
  std::string thorn;
  std::string name;                // local name, e.g. "wave"
  Centering centering = Centering::cell;
  std::vector<ComponentSpec> components;
  VariableRole role = VariableRole::auxiliary;
  std::string rhs;                 // local name of the RHS group when evolved
  int rhs_id = -1;                 // resolved id of the RHS group
  bool checkpoint = false;
  std::string prolongation = "conservative_linear";
  // thorn.yaml `ghosts: N`: the group holds min(N, Grid ghost zones) ghost layers; -1 (absent): the
  // Grid's. Fewer for scratch that no one synchronises (fluxes, right-hand sides, histories).
  int ghosts = -1;
  // Components of vectors and tensors along the Cartesian axes (x, y, z) rather than the grid's
  // coordinate basis (thorn.yaml `basis: cartesian`): symmetry images take Cartesian parities.
  bool cartesian_basis = false;
  // thorn.yaml `if:`: the group has storage only when this holds at start-up (empty: always).
  Condition condition;
  std::string description;
  SourceLocation where;

  std::string full_name() const { return thorn + "::" + name; }
  int ncomp() const { return static_cast<int>(components.size()); }
};

// Expands "vector S" into S1, S2, S3 with parities, and so on.
std::vector<ComponentSpec> expand_tensor(TensorKind kind, const std::string& base_name);

class VariableRegistry {
 public:
  int add(VariableGroupSpec spec);  // returns the id; throws InputError on duplicates
  const VariableGroupSpec& group(int id) const { return groups_.at(static_cast<std::size_t>(id)); }
  VariableGroupSpec& group(int id) { return groups_.at(static_cast<std::size_t>(id)); }
  const std::vector<VariableGroupSpec>& groups() const { return groups_; }
  int size() const { return static_cast<int>(groups_.size()); }
  // "Thorn::group" or, relative to `thorn`, "group". Returns -1 when absent.
  int find(const std::string& name, const std::string& thorn = "") const;
  // Resolves rhs names to ids; throws InputError for an unknown rhs group.
  void resolve_rhs();
  std::vector<int> evolved() const;
  // Groups declared with an `if:` that is false in this run: they have no storage. Kept so that
  // an access to one can be told apart from a typo.
  void add_without_storage(VariableGroupSpec spec);
  const VariableGroupSpec* without_storage(const std::string& name, const std::string& thorn = "") const;

 private:
  std::vector<VariableGroupSpec> groups_;
  std::map<std::string, int> by_name_;
  std::map<std::string, VariableGroupSpec> without_storage_;
};

}  // namespace remnant
