#pragma once
// The stars' positions (the density maxima on either side of z = 0, on the z axis) and the
// density-tracking refinement criterion built on them.
#include <array>

#include "remnant/context.hpp"

namespace remnant::headon {

struct Centres {
  std::array<double, 2> z{0, 0};  // star 0 (z <= 0), star 1 (z > 0)
  bool lower_in_grid = true;      // false with equatorial symmetry: star 0 is star 1's mirror
};

// Service "HeadOn::centres", created at the initial positions.
Centres& centres(Context& ctx);
// HeadOn_TrackStars: the density maxima; collective, the same on every rank and rank count.
void track_stars(Context& ctx);
// HeadOn_RegisterCriterion.
void register_criterion(Context& ctx);
// The level a block should have: the number of radii (decreasing) within which it comes of a centre.
int wanted_level(const Block& b, const Centres& c, const std::vector<double>& radii);

}  // namespace remnant::headon
