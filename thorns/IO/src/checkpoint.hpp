#pragma once
// Checkpoints: everything a bit-identical continuation needs, in one HDF5 file per checkpoint.
//
// Layout ("remnant-checkpoint-2", see checkpoint_header.hpp):
//   /              attrs: format (first), iteration, time, dt, dt_min, dt_max, nranks (of the
//                         writer), coordinates, dimension, nan_count, persistent_thorns, groups,
//                         metadata_checksum, and `complete` = 1 written last
//   /provenance    parfile, thorns, git revision, build type
//   /parameters    every parameter: "Thorn::name<TAB>steerable<TAB>value" lines
//   /persistent/<Thorn>   each thorn's persistent_state text
//   /mesh/blocks   [b][4] (level, i, j, k) in gid order (GridDriver::all_blocks());  /mesh/cells [b][3]
//   /groups/<Thorn::group>     [b][points] per group with `checkpoint: true` (see block_packing.hpp)
//   /checksums/<Thorn::group>  [b] checksum of each block's row
// Blocks are keyed by (level, index), not by rank: recovery works on any number of ranks.
#include <algorithm>
#include <cstdint>
#include <string>

#include "remnant/context.hpp"

namespace remnant::io {

struct CheckpointSettings {
  std::string dir;
  int keep = 2;
  std::int64_t kill_at_iteration = -1;  // test only: SIGKILL in the middle of writing this one
};

// The smallest and largest time step of the run so far (0, 0 before the first step): stored in
// each checkpoint so that recovery can check that its time can follow from its iteration.
struct StepHistory {
  double dt_min = 0, dt_max = 0;
  void observe(double dt) {
    dt_min = dt_min > 0 ? std::min(dt_min, dt) : dt;
    dt_max = std::max(dt_max, dt);
  }
};

// Collective. Returns the path written.
std::string write_checkpoint(Context& ctx, const CheckpointSettings& settings, const StepHistory& history);

// Collective. `mode` is "no", "auto" (newest usable checkpoint in settings.dir, if any) or a file.
// Returns true when the grid, the clock and the thorns' persistent state were restored (and
// `history` from the checkpoint). A checkpoint that fails any check of checkpoint_header.hpp, or
// whose blocks do not match their checksums or the Grid, is reported by name and the previous one
// tried (by the iteration in its name; the stored one must equal it); parameter changes that
// break the continuation are errors (see parameter_record.hpp).
bool recover_checkpoint(Context& ctx, const std::string& mode, const CheckpointSettings& settings,
                        std::string* used_path = nullptr, StepHistory* history = nullptr);

}  // namespace remnant::io
