#pragma once
// Star diagnostics over the grid; the history of every evaluation is published as service
// "Analysis::history" (type remnant::analysis::History) for tests and tools.
#include <cstdint>
#include <string>
#include <vector>

#include <optional>

#include "Analysis/magnetic_diagnostics.hpp"
#include "Analysis/rotation_diagnostics.hpp"
#include "Analysis/collision_diagnostics.hpp"
#include "Analysis/collision_reference.hpp"
#include "remnant/context.hpp"

namespace remnant::analysis {

struct StarDiagnostics {
  std::int64_t iteration = 0;
  double time = 0;
  double rho_c = 0, rho_max = 0, alpha_c = 0, alpha_min = 0, psi_c = 0, psi_max = 0, rest_mass = 0;
  // Rest-mass budget (HydroBase::mass_budget): mass that left through the outer boundary so far, D
  // added by the atmosphere and the error policy so far, and rest_mass + outflow - source, which
  // the scheme keeps constant to round-off.
  double outflow = 0, atmosphere_source = 0, mass_budget = 0;
  bool has_rotation = false;  // Analysis::rotation: the columns of `rotation` follow mass_budget
  RotationDiagnostics rotation;
  // Runs with evolved B only (the extra columns, after the rotation ones).
  std::optional<MagneticDiagnostics> magnetic;
  // Collision diagnostics (only when collision_diagnostics_enabled): appended columns.
  bool collision = false;
  CollisionDiagnostics col;
  double rho_max_norm = 0;  // rho_max / rho_max of the first row
  double rho_max_point_norm = 0;  // col.rho_max_point / that of the first row
  double h_plus = 0;        // sin^2(theta) / D * d(quad_dI)/dt, backward difference to the previous row (0 on the first)
};

struct History {
  std::vector<StarDiagnostics> rows;
  // After a recovery: the first and last rows of the run before it, read back from analysis.tsv
  // (the collision columns' references; Analysis/collision_reference.hpp).
  std::optional<CollisionReference> resumed;
};

// Collective over the grid's ranks; every rank gets the same values.
StarDiagnostics star_diagnostics(Context& ctx);
// The columns of a hydro run, then J .. mode_m2 with rotation, then divB_max, E_mag, E_mag_pol,
// E_mag_tor, B_max with magnetic, then rho_max_norm .. z_rho_max_lower, rho_max_point,
// rho_max_point_norm with collision.
std::string tsv_header(bool rotation, bool magnetic = false, bool collision = false);
std::string tsv_line(const StarDiagnostics& d);

}  // namespace remnant::analysis
