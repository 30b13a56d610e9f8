#pragma once
// Checkpoints: everything a bit-identical continuation needs, in one HDF5 file per checkpoint.
//
// Layout ("remnant-checkpoint-1"):
//   /              attrs: format, iteration, time, dt, nranks (of the writer), coordinates,
//                         dimension, text_checksum, and `complete` = 1 written last
//   /provenance    parfile, thorns, git revision, build type
//   /parameters    every parameter: "Thorn::name<TAB>steerable<TAB>value" lines
//   /persistent/<Thorn>   each thorn's persistent_state text
//   /mesh/blocks   [b][4] (level, i, j, k) in gid order (GridDriver::all_blocks());  /mesh/cells [b][3]
//   /groups/<Thorn::group>     [b][points] per group with `checkpoint: true` (see block_packing.hpp)
//   /checksums/<Thorn::group>  [b] checksum of each block's row
// Blocks are keyed by (level, index), not by rank: recovery works on any number of ranks.
#include <cstdint>
#include <string>

#include "remnant/context.hpp"

namespace remnant::io {

struct CheckpointSettings {
  std::string dir;
  int keep = 2;
  std::int64_t kill_at_iteration = -1;  // test only: SIGKILL in the middle of writing this one
};

// Collective. Returns the path written.
std::string write_checkpoint(Context& ctx, const CheckpointSettings& settings);

// Collective. `mode` is "no", "auto" (newest usable checkpoint in settings.dir, if any) or a file.
// Returns true when the grid, the clock and the thorns' persistent state were restored. A corrupt
// or truncated file is reported by name and the previous one tried; parameter changes that break
// the continuation are errors (see parameter_record.hpp).
bool recover_checkpoint(Context& ctx, const std::string& mode, const CheckpointSettings& settings,
                        std::string* used_path = nullptr);

}  // namespace remnant::io
