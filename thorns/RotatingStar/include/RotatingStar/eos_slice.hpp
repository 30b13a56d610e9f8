#pragma once
// The barotropic slices RotatingStar builds on (besides a polytrope): a table at fixed T (T_min
// when T < 0), either in neutrinoless beta equilibrium or at a fixed Ye, over the table's whole
// density range (800 logarithmic points) for rho(H) and Ye, with eps and p from the table at (rho, T,
// Ye) so that the grid's recovered temperature is T. T or Ye outside the table throw std::runtime_error.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "EOS/tabulated.hpp"
#include "TOV/cold_slice.hpp"

namespace remnant::rotstar {

// A cold piecewise polytrope (the EOS thorn's PiecewisePolytrope: K0 of the first piece, one Gamma per
// piece, the increasing dividing densities), with rho(H) in closed form on each piece.
std::unique_ptr<tov::ColdSlice> piecewise_polytrope_slice(double K0, const std::vector<double>& gammas,
                                                          const std::vector<double>& rho_bounds, double ye);
std::unique_ptr<tov::ColdSlice> beta_slice(const eos::Tabulated<>& table, double T = -1);
std::unique_ptr<tov::ColdSlice> fixed_ye_slice(const eos::Tabulated<>& table, double ye, double T = -1);
// Empty when rho_c lies inside the table's density range, else the error message.
std::string check_density_in_table(const eos::Tabulated<>& table, double rho_c);

}  // namespace remnant::rotstar
