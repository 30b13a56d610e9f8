#pragma once
// One HDF5 file of grid data (volume, slice or line), written collectively through MPI-IO.
//
// Layout ("remnant-grid-1"; b = block, the file's first axis is slowest in every array):
//   /                 attrs: format, iteration, time, coordinates, grid_dimension, dimension, cut,
//                            axes, point, block_cells, variables, git_revision, build_type
//   /provenance       parfile, thorns (+ attrs git_revision, build_type)
//   /blocks/          gid[b], level[b], index[b][3], lo[b][dim], dx[b][dim], fixed[b][3]
//   /coords/<name>    cell centres [b][n_a] per kept axis a (name: x y z, R z phi, r theta phi);
//   /coords/<name>_nodes    cell faces [b][n_a+1]
//   /cartesian_nodes  curvilinear grids only: [b][nodes of the last axis]...[nodes of axis 0][ncart]
//   /data/<Thorn-group.comp>  [b][n_last]...[n_0] (attrs: name, nan_count)
#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

#include "patches.hpp"
#include "provenance.hpp"

namespace remnant::io {

struct GridFileSpec {
  std::string path;  // final name; written as path + ".tmp" and renamed when complete
  CoordinateSystem coordinates = CoordinateSystem::cartesian;
  int grid_dimension = 3;
  Cut cut;
  std::int64_t iteration = 0;
  double time = 0;
  Provenance provenance;
  std::vector<VariableRef> variables;
};

struct GridFileSummary {
  std::vector<PatchMeta> blocks;         // every block in the file, gid order
  std::vector<std::int64_t> nan_counts;  // per variable
  std::uint64_t bytes = 0;               // of variable data
  bool written = false;                  // false when no block intersects the cut
};

// Collective over comm. Throws RunError (naming the file) on any failure; never leaves a partial
// file under the final name.
GridFileSummary write_grid_file(const GridFileSpec& spec, const std::vector<Patch>& local, MPI_Comm comm);

// Names of the grid directions for a coordinate system: x y z / R z phi / r theta phi.
const char* axis_name(CoordinateSystem c, int direction);

}  // namespace remnant::io
