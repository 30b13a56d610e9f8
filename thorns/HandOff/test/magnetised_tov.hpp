#pragma once
// Test helper: a magnetised BU0 TOV star (K = 100, Gamma = 2, rho_c = 1.28e-3) as 3D Carpet data
// (two levels of spacing 1 and 0.5, or a third of 0.25; two components each, ghost and buffer
// zones) and its hand-off with parfiles/handoff_tov_cyl_2d.yaml, HydroBase::magnetic_field =
// evolved. The densitised field sqrt(gamma) B, with P = max(p - p_cut, 0):
// - dipole (default): the poloidal field of A_phi = A_b varpi^2 P^2 and the toroidal field
//   B_phi-hat = A_t varpi z P^2: a pseudo-vector mirror image of itself across z = 0 only;
// - octant_symmetric: the curl of A = A_b P^2 (x, -y, 0) and the same toroidal field: a
//   pseudo-vector mirror image of itself across x = 0, y = 0 and z = 0 (what an octant holds);
// plus, where set, a uniform densitised field everywhere (flux through every plane of the data).
#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Analysis/star_diagnostics.hpp"
#include "HandOff/handoff_state.hpp"
#include "TOV/tov_solver.hpp"
#include "tov_carpet_data.hpp"

namespace remnant {
class Context;
}

namespace remnant::handoff::testing {

constexpr double kAb = 200.0, kAt = 20.0, kPcutFraction = 0.04;

struct MagnetisedTovOptions {
  double toroidal = kAt;
  bool fine = false;                        // a third level (spacing 0.25 on [-9, 9]^3)
  std::array<bool, 3> mirrors{};           // data only at x, y, z >= 0 where set (ReflectionSymmetry)
  bool octant_symmetric = false;           // the octant_symmetric field instead of the dipole
  std::array<double, 3> uniform{};         // a uniform densitised field added everywhere (net flux through the box)
};

struct MagnetisedTov : handoff_test::TovCarpetData {
  double p_cut = kPcutFraction * star.at(0).press;
  MagnetisedTovOptions options;

  explicit MagnetisedTov(const MagnetisedTovOptions& o);
  explicit MagnetisedTov(double toroidal_amplitude = kAt, bool fine = false, bool bitant = false)
      : MagnetisedTov(MagnetisedTovOptions{toroidal_amplitude, fine, {false, false, bitant}, false}) {}

  double P(double r) const;
  double dP(double r) const;
  // The densitised field sqrt(gamma) B (Cartesian components).
  std::array<double, 3> densitised(double x, double y, double z) const;

  // The exact energies (1/2) int psi^-2 |Bt|^2 d^3x of the dipole over the upper half space (z > 0).
  struct Energy {
    double total = 0, toroidal = 0;
  };
  Energy exact_upper_half() const;
};

struct Result {
  handoff::HandOffReport report;
  analysis::StarDiagnostics first, last;
  double outside = 0;  // max |face value| of cells whose centre lies beyond radius 9 (no field in the data)
  double interface_mismatch = 0;  // at the end: interface_flux_mismatch
  double divB_after_refining = 0;  // for inspect callbacks
};

// The hand-off of the data with these overrides (after the defaults: no evolution, Analysis every
// step, HandOff::buffer_zones = 2).
// inspect: called with the finished run (before the report's fields are read from it).
// parfile_text: instead of parfiles/handoff_tov_cyl_2d.yaml (e.g. parfile_without_metric_solve()).
Result hand_off(const MagnetisedTov& data, const std::vector<std::string>& overrides,
                const std::function<void(Context&, Result&)>& inspect = {}, const std::string* parfile_text = nullptr);

// parfiles/handoff_tov_cyl_2d.yaml without XCFC (the flat metric stays): for grids XCFC's
// elliptic solver does not take (periodic Cartesian faces), where only the import is checked.
std::string parfile_without_metric_solve();

// The field the data do not have: max |Bface| on the faces of cells centred beyond radius 9.
double field_outside(Context& ctx);

// Where a block meets a block one level finer (pairs on one rank; not across periodic faces):
// max |coarse face flux - sum of the fine face fluxes on it| / max |face flux| over all faces (0 on
// an unrefined grid). Collective.
double interface_flux_mismatch(Context& ctx);

std::vector<std::string> with(std::vector<std::string> v, const std::vector<std::string>& more);

}  // namespace remnant::handoff::testing
