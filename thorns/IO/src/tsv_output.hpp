#pragma once
// Time series of grid reductions, one TSV file per (variable component, reduction), written by
// rank 0 with full precision so that runs on different rank counts can be compared bit for bit.
// Columns as in the Einstein Toolkit: iteration, time, value; '#' header lines name them.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "remnant/context.hpp"

namespace remnant::io {

struct TsvSeries {
  int group;
  int comp;
  ReductionKind kind;
  bool centre = false;       // value at the cell nearest IO::centre instead of a reduction
  std::string path;
  std::string column;        // e.g. "WaveToy::wave.u norm2"
  std::int64_t nan_rows = 0; // rows written with a NaN value
};

// Resolves "Thorn::group" or "Thorn::group.component" into series; throws InputError otherwise.
std::vector<TsvSeries> plan_tsv_series(const Context& ctx, const std::vector<std::string>& variables,
                                       const std::vector<std::string>& reductions);

// Creates the files (truncating) with their header lines; rank 0 only.
void start_tsv_files(const std::vector<TsvSeries>& series, const Context& ctx);
// After a recovery at `iteration`: keeps the header and the rows up to that iteration, drops later
// rows (written by a run that died after its checkpoint), creates missing files; rank 0 only.
void resume_tsv_files(const std::vector<TsvSeries>& series, const Context& ctx, std::int64_t iteration);
// Reduces and appends one line per file; collective.
void append_tsv_lines(std::vector<TsvSeries>& series, Context& ctx, const std::array<double, 3>& centre);

}  // namespace remnant::io
