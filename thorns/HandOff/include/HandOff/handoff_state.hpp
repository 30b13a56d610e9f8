#pragma once
// What HandOff keeps between its scheduled functions (published as the service "HandOff::state"):
// the 3D data (read once, also when the Grid's initial regrid runs `initial` again), the target,
// the integrals before and after, and the report's numbers (tests read them).
#include <memory>
#include <string>
#include <vector>

#include "HandOff/source_data.hpp"
#include "HandOff/target_domain.hpp"

namespace remnant::handoff {

struct Totals {
  double rest_mass = 0, angular_momentum = 0, energy = 0;
  double magnetic_energy = 0, magnetic_energy_toroidal = 0;  // (1/2) int sqrt(gamma) B^2, its B_phi-hat^2 part
};

struct HandOffReport {
  Totals source_all, source_covered, source_grid;  // 3D: all data, the grid unfolded, the grid itself
  double outside_fraction = 0;   // of the matter's rest mass (rho > atmosphere_rho), outside the unfolded grid
  double atmosphere_rho = 0;      // HandOff::atmosphere_density as used
  double source_matter_rest_mass = 0;  // 3D rest mass of the points with rho > atmosphere_rho
  double raw_rest_mass = 0;       // the grid's rest mass of the interpolated D, before normalisation
  double normalisation = 1;       // factor applied to the imported conserved variables
  Totals imported;                // the grid's integrals of the imported conserved variables
  Totals after;                   // the grid's integrals after the metric solve and the recovery
  double atmosphere_initial_mass = 0;  // the atmosphere's rest mass in cells the data leave empty
  double atmosphere_mass = 0;     // rest mass added by the atmosphere and error policy since import
  long long cells = 0, cells_without_data = 0, cells_partly_covered = 0;
  int max_phi_samples = 1;
  bool has_metric = false, has_lapse = false;
  double psi4_max_rel = 0, psi4_mean_rel = 0, alpha_max_rel = 0, alpha_mean_rel = 0;  // inside the matter
  double psi4_c = 0, gamma13_c = 0, alpha_c = 0, alpha3d_c = 0, rho_c = 0;
  bool after_done = false;
  // Magnetic field (HydroBase::magnetic_field = evolved and Bvec in the data): the grid's energy
  // from the imported faces with the 3D data's gamma^(1/3) (imported) and with the solved psi
  // (after), and max over cells of |net flux| / max over cells of the sum of |face fluxes|.
  bool magnetic = false;
  double divB_relative_max = 0;

};

struct HandOffState {
  std::shared_ptr<SourceData> source;
  TargetDomain target;
  std::vector<std::string> notes;
  HandOffReport report;
};

}  // namespace remnant::handoff
