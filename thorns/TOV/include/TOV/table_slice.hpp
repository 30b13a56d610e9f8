#pragma once
// The cold slice of a tabulated EOS that TOV-type initial data use: neutrinoless beta equilibrium at
// the table's T_min (shared by TOV and HeadOn, so that their stars are the same). The enthalpy
// H(rho) is integrated over `points_per_interval` densities per table interval (nodes included);
// rho(H) is interpolated from it, and Ye, eps and p at that rho come from the table itself, exactly
// as the evolution interpolates it.
#include <memory>

#include "EOS/tabulated.hpp"
#include "TOV/cold_slice.hpp"

namespace remnant::tov {

std::unique_ptr<ColdSlice> cold_beta_slice(const eos::Tabulated<>& table, int points_per_interval = 200);

}  // namespace remnant::tov
