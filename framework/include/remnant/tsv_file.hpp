#pragma once
// Thorns' own TSV time series (analysis.tsv, xcfc.tsv, IO's reductions) across restarts: rows are
// "iteration<TAB>...", header lines start with '#'. A recovered run keeps the rows up to the
// recovered iteration and drops those of the run that died after its checkpoint, so a restarted
// series is the same as a straight one.
#include <cstdint>
#include <string>

#include "remnant/context.hpp"

namespace remnant {

// Keeps header lines and rows with iteration <= last (atomic rewrite; a row cut short by a crash is
// dropped too); returns the number of rows dropped.
std::int64_t trim_tsv_file(const std::string& path, std::int64_t last);

// When a thorn labels its rows: after the iteration's step (analysis, the state at the end of
// iteration n: the checkpoint of n follows them) or before it (a prestep, labelled with the
// iteration the step starts from: the row of n follows the checkpoint of n).
enum class RowTime { after_step, before_step };

// Before a thorn's first row of this run (rank 0): a fresh run creates the file with `header`
// (lines starting with '#', ending in a newline); a recovered run drops the rows written after the
// recovered checkpoint (or creates the file when missing).
void start_or_resume_tsv_file(const Context& ctx, const std::string& path, const std::string& header,
                              RowTime rows = RowTime::after_step);

}  // namespace remnant
