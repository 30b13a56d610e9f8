#pragma once
// HDF5 grid output of a run: which cuts (volume, slices, lines), when (every N iterations and/or
// every dt of simulation time), file names <out_dir>/grid-<cut>.it<8 digits>.h5 with an .xmf
// beside each and a time series grid-<cut>.xmf for ParaView/VisIt.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "patches.hpp"
#include "remnant/context.hpp"
#include "variable_list.hpp"

namespace remnant::io {

struct GridOutputPlan {
  std::vector<VariableRef> variables;
  std::vector<std::string> outputs;  // hdf5_output keywords
  std::array<double, 3> point{0, 0, 0};
  bool xdmf = true;
  std::int64_t every = 0;
  double every_time = 0;
  std::int64_t last_time_index = -1;  // persistent: the last multiple of every_time written
};

// Is an output due now? Updates last_time_index when the time criterion fires.
bool grid_output_due(GridOutputPlan& plan, const Context& ctx);
// Writes every cut; collective.
void write_grid_outputs(const GridOutputPlan& plan, Context& ctx);
// After recovery at `iteration`: removes grid files of later iterations (a dead run's) and
// rewrites the XDMF series; rank 0 only.
void forget_grid_outputs_after(const GridOutputPlan& plan, const Context& ctx, std::int64_t iteration);

std::string series_name(const std::string& output_keyword);  // "grid-volume", "grid-slice_xy"

}  // namespace remnant::io
