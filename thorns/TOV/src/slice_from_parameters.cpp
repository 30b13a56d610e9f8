#include "slice_from_parameters.hpp"

#include "EOS/eos.hpp"
#include "TOV/table_slice.hpp"

namespace remnant::tov {

std::unique_ptr<ColdSlice> slice_from_parameters(const Context& ctx) {
  if (ctx.param<std::string>("TOV", "eos_slice") == "polytrope")
    return polytrope_slice(ctx.param<double>("TOV", "poly_K"), ctx.param<double>("TOV", "poly_gamma"),
                           ctx.param<double>("TOV", "ye"));
  const auto* table = ctx.service<eos::EOS>("eos").tabulated();
  if (!table) throw RunError("TOV::eos_slice = tabulated_beta needs EOS::type = tabulated");
  return cold_beta_slice(*table);
}

DensityRange slice_density_range(const Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto& b = eos.bounds();
  return {b.rho_min, b.rho_max, eos.is_tabulated() ? "the table's range, EOS::table_file" : "EOS::rho_min, EOS::rho_max"};
}

}  // namespace remnant::tov
