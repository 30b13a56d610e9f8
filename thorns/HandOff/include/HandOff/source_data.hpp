#pragma once
// 3D Cartesian data handed over from another run, as the HandOff readers deliver it: one uniform
// node array per refinement level (the union of that level's components, ghost zones removed,
// reflection symmetry unfolded), a validity mask per node, and named fields on it. Points are
// nodes (Carpet's vertex data, or cell centres of Remnant's own output); spacing halves per level.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace remnant::handoff {

struct SourceLevel {
  int level = 0;
  std::array<double, 3> origin{0, 0, 0};  // position of node (0,0,0)
  std::array<double, 3> delta{1, 1, 1};
  std::array<int, 3> n{0, 0, 0};          // nodes per direction
  std::vector<std::uint8_t> valid;        // 1 where every field holds data of this level
  std::map<std::string, std::vector<double>> fields;

  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(n[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(k));
  }
  std::size_t size() const { return static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(n[2]); }
  double x(int d, int i) const { return origin[static_cast<std::size_t>(d)] + i * delta[static_cast<std::size_t>(d)]; }
  bool is_valid(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2] && valid[index(i, j, k)] != 0;
  }
  std::vector<double>& field(const std::string& name) { return fields[name]; }
};

struct SourceData {
  std::string format;                      // carpet | remnant
  std::vector<SourceLevel> levels;         // coarse to fine
  std::int64_t iteration = 0;
  double time = 0;
  std::map<std::string, std::string> file_of;  // variable -> a file that holds it (messages)
  std::array<bool, 3> reflection{false, false, false};  // unfolded mirror planes x^d = 0
  bool ghosts_in_files = true;             // Carpet: CarpetIOHDF5::output_ghost_points
  bool active_regions = false;             // Carpet: components' `active` attributes used (not buffer_zones)
  bool has_metric = false, has_lapse = false;  // the data gave gamma_ij, alpha (kept: gamma^(1/3), alp)
  // Nodal weights (cell volume of a node) are delta^3 on the level that owns the point.
  bool has(const std::string& v) const { return !levels.empty() && levels.front().fields.count(v) != 0; }
  double finest_spacing() const { return levels.empty() ? 0 : levels.back().delta[0]; }
};

// Parity of a Cartesian component under the reflection x^d -> -x^d, from the variable's name:
// vel[i], beta<i> are vectors; Bvec[i] a vector or, with axial_magnetic_field, an axial vector
// (the component normal to the mirror even, the others odd: the Einstein Toolkit's HydroBase::Bvec,
// tagged tensorparity = -1, and Remnant's); g<ij> a tensor; anything else a scalar.
double reflection_parity(const std::string& variable, int direction, bool axial_magnetic_field = false);

}  // namespace remnant::handoff
