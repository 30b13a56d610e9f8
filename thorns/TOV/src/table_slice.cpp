#include "TOV/table_slice.hpp"

#include <cmath>
#include <vector>

#include "EOS/beta_equilibrium.hpp"

namespace remnant::tov {

std::unique_ptr<ColdSlice> cold_beta_slice(const eos::Tabulated<>& table) {
  // A fine logarithmic density grid over the table, beta equilibrium at T_min.
  const auto& b = table.bounds();
  std::vector<double> rhos;
  const int n = 800;
  for (int i = 0; i < n; ++i) rhos.push_back(b.rho_min * std::pow(b.rho_max / b.rho_min, double(i) / (n - 1)));
  rhos.back() = b.rho_max;
  const eos::BetaSlice s = eos::beta_equilibrium_slice(table, b.T_min, rhos);
  return tabulated_slice(s.rho, s.press, s.eps, s.ye);
}

}  // namespace remnant::tov
