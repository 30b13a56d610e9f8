#pragma once
// Test helper: writes files in the layout of the Einstein Toolkit's CarpetIOHDF5 output from
// analytic fields, so that the HandOff reader can be checked without real Carpet files. Each level
// is split into two components (along split_dir), each with cctk_nghostzones ghost points on faces
// inside the level (NaN: reading one shows), refined levels with buffer points (value + 0.5) and
// ghosts (NaN) outside their box, ReflectionSymmetry ghosts (NaN) below reflection planes, and
// components spread over two files (data.file_0.h5, data.file_1.h5) with Carpet's dataset names.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace remnant::handoff::synthetic {

// value(variable, level, x, y, z) of a Carpet variable ("HYDROBASE::rho", "ADMBASE::gxx", ...).
using Field = std::function<double(const std::string&, int, double, double, double)>;

struct LevelLayout {
  double h = 1;                   // spacing
  std::array<double, 3> first{};  // first interior node per direction (>= 0 on reflected directions)
  std::array<int, 3> nodes{};     // interior nodes per direction
  int split_dir = 0;              // the two components split here
};

struct SyntheticCarpet {
  std::array<bool, 3> reflection{true, true, true};
  int ghosts = 3, buffer = 2;
  std::vector<LevelLayout> levels;
  std::vector<std::string> variables;
  std::vector<std::int64_t> iterations{0};
  std::map<std::string, std::vector<std::int64_t>> iterations_of;  // per-variable override
  std::map<int, std::vector<std::int64_t>> extra_iterations_of_level;  // more iterations a level alone has
  double time = 0;
  bool write_parameters = true;  // ReflectionSymmetry::reflection_* in "All Parameters"
  bool parameters_as_bytes = false;  // the dump as a byte array (as CarpetIOHDF5 writes it) or a string
  bool ghosts_written = true;     // false: CarpetIOHDF5::output_ghost_points = "no" (no ghost, no symmetry points)
  std::string ghosts_parameter = "output_ghost_points";  // the one set to "no" (out3D_ghosts: 3D slice output)
  std::string extra_parameters;  // more lines of the parameter dump
  bool write_bbox = true;         // the cctk_bbox attribute (1 on the grid's outer and symmetry faces)
  bool write_active = false;      // Carpet's `active` attribute: the component's points less ghosts and buffers
  std::string stem = "data";
};

// Returns the paths written (two files); with write = false only the paths (other MPI ranks).
std::vector<std::string> write_synthetic_carpet(const std::string& dir, const SyntheticCarpet& spec, const Field& f,
                                                bool write = true);

}  // namespace remnant::handoff::synthetic
