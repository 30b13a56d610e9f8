#pragma once
// Merges the components of each refinement level into one node array per level (SourceLevel):
// ghost zones removed, reflection symmetry unfolded with each variable's parity, and a validity
// mask that holds where every variable has data of that level.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "HandOff/source_data.hpp"

namespace remnant::handoff {

struct Component {
  int level = 0;
  std::array<double, 3> origin{0, 0, 0}, delta{1, 1, 1};
  std::array<int, 3> n{0, 0, 0};       // nodes, ghosts included
  std::array<int, 3> ghosts{0, 0, 0};  // removed on faces inside the domain (cctk_nghostzones)
  std::array<int, 6> outer{-1, -1, -1, -1, -1, -1};  // cctk_bbox: 1 on the grid's outer faces, -1 unknown
  std::string where;                   // "file: dataset" for messages
  // Carpet's `active` attribute: the component's own points (owned, less outer and symmetry
  // boundaries and buffer zones), as inclusive component-local index boxes [lo x, y, z, hi x, y, z].
  // When present it replaces the ghost and buffer rules (no box: the component owns no point).
  std::optional<std::vector<std::array<int, 6>>> active;
};

class LevelBuilder {
 public:
  LevelBuilder(std::array<bool, 3> reflection, int buffer_zones, bool axial_magnetic_field = false)
      : reflection_(reflection), buffer_(buffer_zones), axial_magnetic_field_(axial_magnetic_field) {}
  // data: n[0]*n[1]*n[2] values, x fastest.
  void add(const std::string& variable, Component c, std::vector<double> data);
  std::vector<SourceLevel> build() const;

 private:
  struct Piece {
    Component c;
    std::vector<double> data;
  };
  std::array<bool, 3> reflection_;
  int buffer_;
  bool axial_magnetic_field_;  // Bvec's parity across mirrors (reflection_parity)
  std::map<int, std::map<std::string, std::vector<Piece>>> pieces_;  // level -> variable -> components
};

}  // namespace remnant::handoff
