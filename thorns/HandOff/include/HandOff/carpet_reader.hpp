#pragma once
// Reader of the Einstein Toolkit's CarpetIOHDF5 volume output (3D, one map): datasets named
// "THORN::var it=N tl=0 rl=L c=C" in one or several files per variable, with the attributes origin,
// delta, level, time and cctk_nghostzones. Components of a level are merged into one node array;
// ghost zones are never used (every component face loses cctk_nghostzones points, except faces on
// the coarsest level's outer boundary; refined levels' outer faces lose buffer_zones more); the
// finest level wins where levels overlap (see Sampler). ReflectionSymmetry octant/bitant data are
// unfolded with each component's parity.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "HandOff/source_data.hpp"

namespace remnant::handoff {

struct CarpetOptions {
  std::vector<std::string> files;           // paths (globs already expanded)
  std::int64_t iteration = -1;              // -1: the latest iteration common to every variable read
  std::vector<std::string> variables;       // canonical names to read (rho, vel[0], gxx, Ye, ...)
  std::vector<std::string> required;        // subset that must be present
  std::array<bool, 3> reflection{false, false, false};  // mirror planes given by the user
  bool reflection_from_file = true;         // also read ReflectionSymmetry::reflection_* from the files
  int buffer_zones = 0;                     // extra points removed at refined levels' outer faces
  bool axial_magnetic_field = true;         // Bvec unfolded as an axial vector (false: as vel)
};

// The canonical name of a Carpet variable ("HYDROBASE::vel[1]" -> "vel[1]", "HYDROBASE::Y_e" ->
// "Ye", "ADMBASE::gxx" -> "gxx"); empty for variables HandOff does not use.
std::string canonical_carpet_name(const std::string& full_name);

// Throws RunError naming the file and variable for missing files, variables or iterations.
SourceData read_carpet(const CarpetOptions& options);

// Expands globs; a pattern that matches nothing is an error naming it.
std::vector<std::string> expand_file_patterns(const std::vector<std::string>& patterns);

}  // namespace remnant::handoff
