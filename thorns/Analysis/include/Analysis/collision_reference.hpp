#pragma once
// The collision columns refer to earlier rows: rho_max_norm and rho_max_point_norm divide by the
// first row's values, h_plus differentiates quad_dI against the previous row. A recovered run has
// neither row in memory; they are read back from the analysis.tsv it resumes (kept up to the
// recovered iteration by start_or_resume_tsv_file), so that a restarted series is the same as a
// straight one. Without this, a run recovered at iteration n normalised by its row n + every
// (measured: the 3D head-on run at dx 0.375, recovered at 474, divided by rho_max at t = 174,
// 3 % above rho_max(0)).
#include <istream>
#include <optional>
#include <string>

#include "remnant/context.hpp"

namespace remnant::analysis {

struct CollisionReference {
  double rho_max = 0, rho_max_point = 0;  // of the file's first row
  bool has_previous = false;              // the last row, for h_plus (false: none)
  double previous_time = 0, previous_quad_dI = 0;
};

// From the text of an analysis.tsv: its '#' header names the columns (any rotation or magnetic
// columns before the collision ones); nothing when the header lacks one of rho_max, rho_max_point,
// time, quad_dI or the file has no complete row.
std::optional<CollisionReference> collision_reference_from_tsv(std::istream& in);

// Collective: rank 0 reads `path` (after its rows beyond the recovered iteration were dropped) and
// every rank gets the same answer; nothing (with a message) when the file or its rows are missing.
std::optional<CollisionReference> resumed_collision_reference(const Context& ctx, const std::string& path);

}  // namespace remnant::analysis
