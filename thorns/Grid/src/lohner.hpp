#pragma once
// The Löhner (1987) error estimator, as MPI-AMRVAC uses it: per cell the normalised second
// derivative
//   E = sqrt( sum_kl (d_k d_l u)^2 / sum_kl ( |d_k u|_{+l} + |d_k u|_{-l} + eps * avg_kl |u| )^2 )
// from undivided differences over the +-1 neighbours (the filter eps keeps small ripples on a
// large background from triggering refinement). A block wishes refinement where max E exceeds
// the threshold, and coarsening where it stays below derefine_ratio * threshold.
#include "remnant/grid.hpp"

namespace remnant::grid {

// Max of E over the interior of a block; the ghosts of `u` must be current. With `log_scale` the
// estimator works on log10(max(|u|, tiny)).
double lohner_estimate(const Block& block, const Field& u, int dimension, bool log_scale, double filter);

// +1, 0 or -1 from an estimate.
int lohner_wish(double estimate, double threshold, double derefine_ratio);

}  // namespace remnant::grid
