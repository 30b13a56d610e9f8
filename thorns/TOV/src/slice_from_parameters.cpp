#include "slice_from_parameters.hpp"

#include <cmath>
#include <vector>

#include "EOS/beta_equilibrium.hpp"
#include "EOS/eos.hpp"

namespace remnant::tov {

std::unique_ptr<ColdSlice> slice_from_parameters(const Context& ctx) {
  if (ctx.param<std::string>("TOV", "eos_slice") == "polytrope")
    return polytrope_slice(ctx.param<double>("TOV", "poly_K"), ctx.param<double>("TOV", "poly_gamma"),
                           ctx.param<double>("TOV", "ye"));
  const auto* table = ctx.service<eos::EOS>("eos").tabulated();
  if (!table) throw RunError("TOV::eos_slice = tabulated_beta needs EOS::type = tabulated");
  // A fine logarithmic density grid over the table, beta equilibrium at T_min.
  const auto& b = table->bounds();
  std::vector<double> rhos;
  const int n = 800;
  for (int i = 0; i < n; ++i) rhos.push_back(b.rho_min * std::pow(b.rho_max / b.rho_min, double(i) / (n - 1)));
  rhos.back() = b.rho_max;
  const eos::BetaSlice s = eos::beta_equilibrium_slice(*table, b.T_min, rhos);
  return tabulated_slice(s.rho, s.press, s.eps, s.ye);
}

DensityRange slice_density_range(const Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto& b = eos.bounds();
  return {b.rho_min, b.rho_max, eos.is_tabulated() ? "the table's range, EOS::table_file" : "EOS::rho_min, EOS::rho_max"};
}

}  // namespace remnant::tov
