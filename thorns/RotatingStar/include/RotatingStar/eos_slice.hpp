#pragma once
// The cold slices RotatingStar builds on: a polytrope, or the cold (T_min) neutrinoless
// beta-equilibrium slice of a table over its whole density range (800 logarithmic points).
#include <memory>
#include <string>

#include "EOS/tabulated.hpp"
#include "TOV/cold_slice.hpp"

namespace remnant::rotstar {

std::unique_ptr<tov::ColdSlice> beta_slice(const eos::Tabulated<>& table);
// Empty when rho_c lies inside the table's density range, else the error message.
std::string check_density_in_table(const eos::Tabulated<>& table, double rho_c);

}  // namespace remnant::rotstar
