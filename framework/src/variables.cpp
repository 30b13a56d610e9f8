#include "remnant/variables.hpp"

#include <algorithm>

namespace remnant {

std::array<int, 3> staggering(Centering c) {
  switch (c) {
    case Centering::cell: return {0, 0, 0};
    case Centering::face_x: return {1, 0, 0};
    case Centering::face_y: return {0, 1, 0};
    case Centering::face_z: return {0, 0, 1};
    case Centering::edge_x: return {0, 1, 1};
    case Centering::edge_y: return {1, 0, 1};
    case Centering::edge_z: return {1, 1, 0};
    case Centering::vertex: return {1, 1, 1};
  }
  return {0, 0, 0};
}

const char* to_string(Centering c) {
  switch (c) {
    case Centering::cell: return "cell";
    case Centering::face_x: return "face_x";
    case Centering::face_y: return "face_y";
    case Centering::face_z: return "face_z";
    case Centering::edge_x: return "edge_x";
    case Centering::edge_y: return "edge_y";
    case Centering::edge_z: return "edge_z";
    case Centering::vertex: return "vertex";
  }
  return "?";
}

const char* to_string(TensorKind k) {
  switch (k) {
    case TensorKind::scalar: return "scalar";
    case TensorKind::vector: return "vector";
    case TensorKind::covector: return "covector";
    case TensorKind::axial_vector: return "axial_vector";
    case TensorKind::tensor_uu: return "tensor_uu";
    case TensorKind::tensor_dd: return "tensor_dd";
  }
  return "?";
}

int component_count(TensorKind k) {
  switch (k) {
    case TensorKind::scalar: return 1;
    case TensorKind::vector:
    case TensorKind::covector:
    case TensorKind::axial_vector: return 3;
    case TensorKind::tensor_uu:
    case TensorKind::tensor_dd: return 6;
  }
  return 1;
}

std::vector<ComponentSpec> expand_tensor(TensorKind kind, const std::string& base) {
  std::vector<ComponentSpec> out;
  auto make = [&](std::string name, int a, int b) {
    ComponentSpec c;
    c.name = std::move(name);
    c.kind = kind;
    c.indices = {a, b};
    // A reflection x^d -> -x^d flips the sign once per tensor index equal to d. Upper and lower
    // indices transform alike under reflections. Axial vectors (B) pick up one extra sign.
    for (int d = 0; d < 3; ++d) {
      int flips = (a == d) + (b == d);
      int sign = (flips % 2 == 0) ? 1 : -1;
      if (kind == TensorKind::axial_vector) sign = -sign;
      c.reflection_parity[static_cast<std::size_t>(d)] = sign;
    }
    out.push_back(std::move(c));
  };
  switch (kind) {
    case TensorKind::scalar: make(base, -1, -1); break;
    case TensorKind::vector:
    case TensorKind::covector:
    case TensorKind::axial_vector:
      for (int a = 0; a < 3; ++a) make(base + std::to_string(a + 1), a, -1);
      break;
    case TensorKind::tensor_uu:
    case TensorKind::tensor_dd:
      for (int a = 0; a < 3; ++a)
        for (int b = a; b < 3; ++b) make(base + std::to_string(a + 1) + std::to_string(b + 1), a, b);
      break;
  }
  return out;
}

int VariableRegistry::add(VariableGroupSpec spec) {
  const std::string full = spec.full_name();
  if (auto it = by_name_.find(full); it != by_name_.end()) {
    throw InputError(spec.where, "variable group '" + full + "' is already declared at " +
                                     groups_[static_cast<std::size_t>(it->second)].where.str());
  }
  spec.id = static_cast<int>(groups_.size());
  by_name_[full] = spec.id;
  groups_.push_back(std::move(spec));
  return groups_.back().id;
}

int VariableRegistry::find(const std::string& name, const std::string& thorn) const {
  if (name.find("::") == std::string::npos && !thorn.empty()) {
    if (auto it = by_name_.find(thorn + "::" + name); it != by_name_.end()) return it->second;
    return -1;
  }
  if (auto it = by_name_.find(name); it != by_name_.end()) return it->second;
  return -1;
}

void VariableRegistry::add_without_storage(VariableGroupSpec spec) {
  const std::string key = spec.full_name();
  without_storage_.emplace(key, std::move(spec));
}

const VariableGroupSpec* VariableRegistry::without_storage(const std::string& name, const std::string& thorn) const {
  const std::string key = name.find("::") == std::string::npos && !thorn.empty() ? thorn + "::" + name : name;
  auto it = without_storage_.find(key);
  return it == without_storage_.end() ? nullptr : &it->second;
}

void VariableRegistry::resolve_rhs() {
  for (auto& g : groups_) {
    if (g.rhs.empty()) continue;
    int id = find(g.rhs, g.thorn);
    if (id < 0) throw InputError(g.where, "group '" + g.full_name() + "' names rhs '" + g.rhs +
                                              "', which is not a declared variable group");
    const auto& r = groups_[static_cast<std::size_t>(id)];
    if (r.ncomp() != g.ncomp() || r.centering != g.centering)
      throw InputError(g.where, "rhs group '" + r.full_name() + "' must have the same components "
                                "and centering as '" + g.full_name() + "'");
    g.rhs_id = id;
  }
}

std::vector<int> VariableRegistry::evolved() const {
  std::vector<int> out;
  for (const auto& g : groups_)
    if (g.role == VariableRole::evolved) out.push_back(g.id);
  return out;
}

}  // namespace remnant
