#pragma once
// Per-cell diagnostics of the face fields for the TSV reductions of IO (any rank count, across
// regrids): |div B| dx_min / B_ref with B_ref the largest |face value| on the whole grid (reduce
// with `maximum` for divB_max), and b2 = |B|^2 / 2 of the face means (its volume integral is the
// magnetic energy in flat space). A local normalisation (max |B| among nearby cells) is
// ill-conditioned where the field vanishes: in the field loop's diffusion tail (|B| ~ 1e-12 of the
// loop's) it reached O(1) while |div B| dx stayed at 3e-15 of the loop's field.
#include "remnant/context.hpp"
#include "remnant/grid.hpp"

namespace remnant::mhd_tests {

// Largest |value| over the interior faces of the block.
double max_face_value(Block& b, const Field& bx, const Field& by, const Field& bz);
// absB = |B| of the face means where it is at least floor * b_ref, else 0.
void cell_diagnostics(Block& b, const Field& bx, const Field& by, const Field& bz, double b_ref, double floor,
                      const Field& div_rel, const Field& b2, const Field& abs_b);

// Scheduled (and called after the initial face fields): fills MHDTests::divB, b2, absB on every
// local block.
void magnetic_diagnostics(Context& ctx);

}  // namespace remnant::mhd_tests
