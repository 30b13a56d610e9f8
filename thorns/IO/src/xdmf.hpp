#pragma once
// XDMF (version 2) descriptions of grid files, so that ParaView and VisIt open them directly:
// one Uniform grid per block whose arrays are hyperslabs of the file's [block][...] datasets.
// Cartesian data use rectilinear meshes (2DRectMesh/3DRectMesh from the node coordinates);
// cylindrical and spherical data use structured meshes (2DSMesh/3DSMesh) on the Cartesian node
// positions /cartesian_nodes. 1D files have no XDMF (plot them with utils/plot_slice).
#include <string>

#include "grid_file.hpp"

namespace remnant::io {

// The <Grid CollectionType="Spatial"> element for one file (referenced by its base name h5_name).
std::string xdmf_grid_element(const GridFileSpec& spec, const GridFileSummary& summary, const std::string& h5_name);

// Writes a complete XDMF document holding these grid elements (atomically: tmp + rename).
void write_xdmf_document(const std::string& path, const std::string& grids, bool temporal);

// Rewrites the time series `<dir>/<series>.xmf`: an XInclude of each per-iteration file <series>.it*.xmf
// with iteration <= last (files of a dead run beyond a recovered iteration are left out).
void write_xdmf_series(const std::string& dir, const std::string& series, std::int64_t last);

// Iteration encoded in "<series>.it<digits>.<ext>", or -1 when the name does not match.
std::int64_t iteration_of(const std::string& filename, const std::string& series, const std::string& ext);

}  // namespace remnant::io
