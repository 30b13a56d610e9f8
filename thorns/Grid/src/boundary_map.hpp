#pragma once
// Where a ghost region's data come from: the ghost images of the shared domain model
// (remnant/domain.hpp) for the Grid's faces. Every non-outflow domain face is an index map on the
// global point indices of a level: periodic faces shift, reflect/axis/origin faces mirror (the
// origin also mirrors theta about pi/2, and in 3D the axis and origin shift phi by pi). A map
// carries, per coordinate direction, the sign the coordinate basis vector picks up; the sign of a
// component is the product over its tensor indices, with one more sign for an axial vector when
// the map contains an odd number of physical reflections. No per-variable code.
#include <array>
#include <cstdint>
#include <optional>

#include "Grid/grid_config.hpp"
#include "remnant/domain.hpp"
#include "remnant/variables.hpp"

namespace remnant::grid {

using Range = std::array<std::int64_t, 3>;
// Boxes of global point indices and their index maps: the shared domain model's.
using remnant::GlobalBox;
using remnant::IndexMap;
using remnant::intersect;

class BoundaryMaps {
 public:
  explicit BoundaryMaps(const GridConfig& config);
  // The map that takes the box (each direction entirely inside, below or above the domain) of a
  // centering with staggering `stagger` on `level` into the domain; nullopt when it lies beyond
  // an outflow face in some direction (the outflow pass fills it).
  std::optional<IndexMap> image(int level, const std::array<int, 3>& stagger, const GlobalBox& box) const;
  // Points per direction on a level (cells; faces have one more in their direction).
  Range cells_on_level(int level) const;

 private:
  GridConfig config_;
  DomainFaces faces_;
  std::int64_t theta_cells_to_pi_ = 0;  // level 0 cells in [0, pi] (the origin's theta mirror)
};

}  // namespace remnant::grid
