#pragma once
// What one output file holds: patches of cells cut from the local blocks -- whole blocks (volume
// output), one plane of cells (2D slices of a 3D grid) or one row (1D lines along an axis).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "remnant/grid.hpp"
#include "variable_list.hpp"

namespace remnant::io {

// Which cells of the grid a file holds.
struct Cut {
  std::string name;            // "volume", "xy", "xz", "yz", "x", "y", "z"
  std::vector<int> axes;       // grid directions kept, ascending (the file's dimensions)
  std::array<double, 3> point{0, 0, 0};  // where slices and lines pass (grid coordinates)
};

// Parses an IO::hdf5_output keyword (volume, slice_xy, ..., line_z) for a grid of `dimension`.
// Throws RunError when the cut needs more directions than the grid has.
Cut make_cut(const std::string& keyword, int dimension, const std::array<double, 3>& point);

struct PatchMeta {
  std::int64_t gid = 0;
  std::int64_t level = 0;
  std::array<std::int64_t, 3> index{0, 0, 0};
  std::array<std::int64_t, 3> n{1, 1, 1};     // cells along the file's axes (unused: 1)
  std::array<double, 3> lo{0, 0, 0};         // lower face along the file's axes
  std::array<double, 3> dx{1, 1, 1};
  std::array<double, 3> centre3{0, 0, 0};    // grid coordinates of the cut's fixed directions
};

struct Patch {
  PatchMeta meta;
  std::vector<std::vector<double>> values;   // per variable: cells, first axis fastest
};

// This rank's patches of `cut`, sorted by gid.
std::vector<Patch> extract_patches(std::span<Block* const> blocks, int dimension, const Cut& cut,
                                   const std::vector<VariableRef>& vars);

}  // namespace remnant::io
