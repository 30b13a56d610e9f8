#pragma once
// Where a ghost region's data come from. Every non-outflow domain face is an index map on the
// global point indices of a level: periodic faces shift, reflect/axis/origin faces mirror (the
// origin also mirrors theta about pi/2, and in 3D the axis and origin shift phi by pi). A map
// carries, per coordinate direction, the sign the coordinate basis vector picks up; the sign of a
// component is the product over its tensor indices, with one more sign for an axial vector when
// the map contains an odd number of physical reflections. No per-variable code.
#include <array>
#include <cstdint>
#include <optional>

#include "Grid/grid_config.hpp"
#include "remnant/variables.hpp"

namespace remnant::grid {

using Range = std::array<std::int64_t, 3>;

// A box of global point indices on one level, [lo, hi) per direction.
struct GlobalBox {
  Range lo{0, 0, 0}, hi{1, 1, 1};
  bool empty() const { return lo[0] >= hi[0] || lo[1] >= hi[1] || lo[2] >= hi[2]; }
};
GlobalBox intersect(const GlobalBox& a, const GlobalBox& b);

// image(i)_d = sigma_d * i_d + shift_d.
struct IndexMap {
  std::array<int, 3> sigma{1, 1, 1};
  Range shift{0, 0, 0};
  std::array<int, 3> basis_sign{1, 1, 1};
  bool mirrored = false;

  std::int64_t apply(int d, std::int64_t i) const {
    return sigma[static_cast<std::size_t>(d)] * i + shift[static_cast<std::size_t>(d)];
  }
  GlobalBox apply(const GlobalBox& b) const;
  GlobalBox inverse(const GlobalBox& b) const;
  bool preserves_orientation() const { return sigma[0] > 0 && sigma[1] > 0 && sigma[2] > 0; }
  double sign(const ComponentSpec& c) const;
};

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
  std::int64_t theta_cells_to_pi_ = 0;  // level 0 cells in [0, pi] (the origin's theta mirror)
};

}  // namespace remnant::grid
