#pragma once
// Time series of grid reductions, one TSV file per (variable component, reduction), written by
// rank 0 with full precision so that runs on different rank counts can be compared bit for bit.
#include <string>
#include <vector>

#include "remnant/context.hpp"

namespace remnant::io {

struct TsvSeries {
  int group;
  int comp;
  ReductionKind kind;
  std::string path;
  std::string column;  // e.g. "WaveToy::wave.u norm2"
};

// Resolves "Thorn::group" or "Thorn::group.component" into series; throws InputError otherwise.
std::vector<TsvSeries> plan_tsv_series(const Context& ctx, const std::vector<std::string>& variables,
                                       const std::vector<std::string>& reductions);

// Creates the files (truncating) with their header lines; rank 0 only.
void start_tsv_files(const std::vector<TsvSeries>& series, const Context& ctx);
// Reduces and appends one line per file; collective.
void append_tsv_lines(const std::vector<TsvSeries>& series, Context& ctx);

}  // namespace remnant::io
