#pragma once
// Integrals of the 3D data: each point counts once, on the finest level that has it, with the
// volume delta^3 of its level. Rest mass M0 = sum sqrt(gamma) rho W dV, angular momentum about z
// J = sum (x S_y - y S_x) dV, energy E = sum (tau + D) dV (all densitised by sqrt(gamma)), magnetic energy sum (1/2) sqrt(gamma) B^2 dV; over
// all the data, over the target's covered region (the grid unfolded by its mirrors), and over the
// grid itself (its fundamental domain, what the grid's own integrals compare with).
#include "HandOff/source_data.hpp"
#include "HandOff/target_domain.hpp"

namespace remnant::handoff {

struct Integrals {
  double rest_mass = 0, angular_momentum = 0, energy = 0;
  double matter_rest_mass = 0;  // of the points denser than the data's atmosphere (SourceIntegrals)
  double magnetic_energy = 0, magnetic_energy_toroidal = 0;  // where the data have Emag, Emagtor
};

// outside_fraction: of the matter, the rest mass of points with rho > atmosphere_rho: an Einstein
// Toolkit run's atmosphere floor fills its whole domain (GRHydro's rho_abs_min = 1e-10 over
// [-240, 240]^3 is 1.5 % of a TOV star's rest mass), which a grid around the star need not hold.
struct SourceIntegrals {
  Integrals all, covered, grid;
  double atmosphere_rho = 0;  // the density at or below which a point counts as atmosphere
  double rho_min = 0;         // the data's smallest rho
  double outside_fraction() const { return all.matter_rest_mass > 0 ? 1 - covered.matter_rest_mass / all.matter_rest_mass : 0; }
};

// The data's smallest rho over valid points (its atmosphere floor, where it has one).
double smallest_density(const SourceData& src);

SourceIntegrals integrate_source(const SourceData& src, const TargetDomain& target, double atmosphere_rho = 0);

}  // namespace remnant::handoff
