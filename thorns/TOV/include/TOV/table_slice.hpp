#pragma once
// The cold slice of a tabulated EOS that TOV-type initial data use: neutrinoless beta equilibrium at
// the table's T_min (shared by TOV and HeadOn, so that their stars are the same). Ye, eps and p at a
// density come from the table itself, exactly as the evolution interpolates it; the enthalpy H(rho)
// is integrated from those values piece by piece between the kinks of the interpolated table (its
// density nodes and the densities where beta-equilibrium Ye crosses a node of the Ye axis), about
// `points_per_interval` samples per density interval of the table, so that dp/dH = e + p holds to
// O(1e-7) at every density (src/enthalpy_curve.hpp).
#include <memory>
#include <vector>

#include "EOS/tabulated.hpp"
#include "TOV/cold_slice.hpp"

namespace remnant::tov {

std::unique_ptr<ColdSlice> cold_beta_slice(const eos::Tabulated<>& table, int points_per_interval = 200);

// The state of the slice at rho: Ye of beta equilibrium at (rho, T_min), eps and p of the table there.
ColdState cold_beta_state(const eos::Tabulated<>& table, double rho);

// ln rho of the slice's kinks, ascending from ln rho_min to ln rho_max (both included): the table's
// density nodes and the Ye-node crossings of beta-equilibrium Ye, found on `scan_points` per interval.
std::vector<double> slice_kinks(const eos::Tabulated<>& table, int scan_points = 64);

}  // namespace remnant::tov
