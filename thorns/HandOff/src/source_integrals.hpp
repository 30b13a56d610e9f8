#pragma once
// Integrals of the 3D data: each point counts once, on the finest level that has it, with the
// volume delta^3 of its level. Rest mass M0 = sum sqrt(gamma) rho W dV, angular momentum about z
// J = sum (x S_y - y S_x) dV, energy E = sum (tau + D) dV (all densitised by sqrt(gamma)); over
// all the data, over the target's covered region (the grid unfolded by its mirrors), and over the
// grid itself (its fundamental domain, what the grid's own integrals compare with).
#include "HandOff/source_data.hpp"
#include "HandOff/target_domain.hpp"

namespace remnant::handoff {

struct Integrals {
  double rest_mass = 0, angular_momentum = 0, energy = 0;
};

struct SourceIntegrals {
  Integrals all, covered, grid;
  double outside_fraction() const { return all.rest_mass > 0 ? 1 - covered.rest_mass / all.rest_mass : 0; }
};

SourceIntegrals integrate_source(const SourceData& src, const TargetDomain& target);

}  // namespace remnant::handoff
