#pragma once
// Everything of a checkpoint that recovery uses except the block data, with one checksum over
// all of it (the `metadata_checksum` attribute), and the checks that decide whether a checkpoint
// may be used: the checksum, then physical and parfile sense (see validate_checkpoint_header).
// The block data are covered by one checksum per block and group (/checksums/<group>), and those
// tables are part of the metadata checksum: no byte that recovery uses is unchecked.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "remnant/context.hpp"

namespace remnant::io {

inline constexpr const char* checkpoint_format = "remnant-checkpoint-2";

struct CheckpointGroup {
  std::string name;        // Thorn::group
  std::string components;  // comma separated
  std::string centering;
  std::uint64_t width = 0;           // doubles per block row
  std::vector<std::uint64_t> sums;   // one checksum per block row
};

struct CheckpointHeader {
  std::string format = checkpoint_format;
  std::int64_t iteration = 0;
  double time = 0, dt = 0;
  // The smallest and largest step of the run's history up to this checkpoint (0, 0 before the
  // first step): the time must lie between iteration * dt_min and iteration * dt_max.
  double dt_min = 0, dt_max = 0;
  std::int64_t nranks = 1, dimension = 0, nan_count = 0;
  std::string coordinates, parameters, thorns, git;
  std::vector<std::pair<std::string, std::string>> states;  // thorn, persistent state text
  std::vector<std::int64_t> blocks;  // [b][4]: level, i, j, k
  std::vector<std::int64_t> cells;   // [b][3]
  std::vector<CheckpointGroup> groups;

  std::size_t block_count() const { return blocks.size() / 4; }
};

// The checksum over every field above, in a fixed order with lengths (no two headers that differ
// in one byte share it by construction of the sequence; a one-bit change always changes it).
std::uint64_t metadata_checksum(const CheckpointHeader& h);

// Writes the scalar attributes, the name lists and `digest` (metadata_checksum(h) of rank 0,
// which alone holds the gathered tables; collective on a parallel file); `format` (first), the datasets and `complete` (last)
// are written by the caller.
void write_header_attributes(hid_t file, const CheckpointHeader& h, std::uint64_t digest);

// Reads every field and verifies the metadata checksum; throws RunError with the reason
// ("it is not a Remnant checkpoint", "it is incomplete", "... checksum ...").
CheckpointHeader read_checkpoint_header(hid_t file);

// What this run expects of a checkpoint.
struct CheckpointExpectations {
  int dimension = 0;
  std::string coordinates;
  std::vector<std::string> persistent_thorns;
  std::vector<CheckpointGroup> groups;  // name, components, centering of each checkpointed group
};
CheckpointExpectations expectations_of(const Context& ctx);

// Physical and parfile sense of a header whose checksum matched; throws RunError with the reason.
// `path`: its file name must carry the stored iteration (checkpoint.it<N>.h5; other names skip
// that check, e.g. an IO::recover path to a copy).
void validate_checkpoint_header(const CheckpointHeader& h, const std::string& path, const CheckpointExpectations& e);

// Opens `path` (serial, read-only), reads, verifies and validates its header; throws RunError.
CheckpointHeader inspect_checkpoint(const std::string& path, const CheckpointExpectations& e);

// Reads the rows `rows` of group `g` and checks each against its checksum; throws RunError.
std::vector<double> read_verified_rows(hid_t file, const CheckpointGroup& g, const std::vector<std::size_t>& rows);

}  // namespace remnant::io
