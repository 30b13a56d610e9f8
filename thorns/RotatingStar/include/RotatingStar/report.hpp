#pragma once
// The global quantities of a model as (name, value) rows, in one order for the log, the TSV files
// and remnant-rotstar (name = value lines); names carry their units (code units G = c = M_sun = 1;
// B_max_gauss in Gauss). H_mag, H_over_W and B_max are 0 for an unmagnetised star.
#include <string>
#include <utility>
#include <vector>

#include "HydroBase/magnetic_units.hpp"
#include "RotatingStar/rns_solver.hpp"

namespace remnant::rotstar {

inline std::vector<std::pair<std::string, double>> global_rows(const RnsGlobals& g) {
  return {{"rho_c", g.rho_c},         {"rho_max", g.rho_max},     {"M_komar", g.M_komar},
          {"M_adm", g.M_adm},         {"M_rest", g.M_rest},       {"M_proper", g.M_proper},
          {"J", g.J},                 {"J_over_M2", g.J / (g.M_komar * g.M_komar)},
          {"T_kin", g.T_kin},         {"W_bind", g.W_bind},       {"T_over_W", g.T_over_W},
          {"r_e", g.r_e},             {"r_p", g.r_p},             {"R_circ", g.R_circ},
          {"axis_ratio", g.axis_ratio}, {"Omega_c", g.omega_c},   {"Omega_e", g.omega_e},
          {"H_mag", g.H_mag},         {"H_over_W", g.H_over_W},   {"B_max", g.B_max},
          {"B_max_gauss", g.B_max * hydrobase::kGaussPerCodeB},
          {"alpha_c", g.alpha_c},     {"psi_c", g.psi_c},         {"GRV2", g.grv2},
          {"GRV3", g.grv3},           {"GRV2_GR", g.grv2_gr},     {"GRV3_GR", g.grv3_gr},           {"iterations", double(g.iterations)}};
}

}  // namespace remnant::rotstar
