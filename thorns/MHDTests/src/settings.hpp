#pragma once
// The thorn's parameters read once into the problem tables' structs.
#include "problems.hpp"
#include "remnant/context.hpp"

namespace remnant::mhd_tests {

struct Settings {
  Problem problem = Problem::balsara1;
  double discontinuity = 0, ye = 0.5;
  FieldLoopParams loop;
  BlastParams blast;
  RotorParams rotor;
};

// Throws InputError naming MHDTests::problem when it is `none`.
Settings settings_from(const Context& ctx);

// The fluid state of the problem at a point (B of the 2D problems included, from the formulas).
FluidState state_at(const Settings& s, double x, double y);

}  // namespace remnant::mhd_tests
