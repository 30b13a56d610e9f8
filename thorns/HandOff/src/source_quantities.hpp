#pragma once
// From what a 3D code wrote to what the hand-off needs at every source point: missing variables
// mapped from the EOS (each mapping noted for the log), the data checked against the EOS, then the
// gauge-independent densitised conserved variables sqrt(gamma) (D, S_i, tau, D Ye) (paper, "Spacetime
// Solvers"), gamma^(1/3) and the lapse. Cartesian components throughout.
#include <string>
#include <vector>

#include "EOS/eos.hpp"
#include "HandOff/source_data.hpp"

namespace remnant::handoff {

struct MissingPolicy {
  bool from_eos = true;     // false: a missing variable is an error
  double ye = 0.5;          // Ye where the data have none
  double eos_tolerance = 0; // max |p_data / p_EOS(rho, eps, Ye) - 1| where rho > 1e-6 rho_max (0: no check)
};

// The fields the hand-off interpolates, after complete_source and add_conserved.
inline const std::vector<std::string>& conserved_fields() {
  static const std::vector<std::string> f{"Dt", "St[0]", "St[1]", "St[2]", "taut", "DYet"};
  return f;
}
inline const std::vector<std::string>& primitive_fields() {
  static const std::vector<std::string> f{"rho", "eps", "Ye", "vel[0]", "vel[1]", "vel[2]", "gamma13", "alp"};
  return f;
}

// Fills eps, press, Ye, vel where the data lack them (or throws when policy.from_eos is false),
// and checks press against the EOS; returns the notes for the log.
std::vector<std::string> complete_source(SourceData& src, const eos::EOS& eos, const MissingPolicy& policy);
// Adds Dt, St[i], taut, DYet (unless present), gamma13 and alp; notes for the log.
std::vector<std::string> add_conserved(SourceData& src);

}  // namespace remnant::handoff
