#include "RotatingStar/eos_slice.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "EOS/beta_equilibrium.hpp"

namespace remnant::rotstar {

std::unique_ptr<tov::ColdSlice> beta_slice(const eos::Tabulated<>& table) {
  const auto& b = table.bounds();
  std::vector<double> rhos;
  const int n = 800;
  for (int i = 0; i < n; ++i) rhos.push_back(b.rho_min * std::pow(b.rho_max / b.rho_min, double(i) / (n - 1)));
  rhos.back() = b.rho_max;
  const eos::BetaSlice s = eos::beta_equilibrium_slice(table, b.T_min, rhos);
  return tov::tabulated_slice(s.rho, s.press, s.eps, s.ye);
}

std::string check_density_in_table(const eos::Tabulated<>& table, double rho_c) {
  const auto& b = table.bounds();
  if (rho_c > b.rho_min && rho_c < b.rho_max) return "";
  char msg[256];
  std::snprintf(msg, sizeof msg, "central density %g is outside the EOS table's density range (%g, %g) (code units)", rho_c,
                b.rho_min, b.rho_max);
  return msg;
}

}  // namespace remnant::rotstar
