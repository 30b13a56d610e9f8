#pragma once
// The cold slice of a tabulated EOS that TOV-type initial data use: neutrinoless beta equilibrium
// at the table's T_min on 800 densities spaced logarithmically over the table (shared by TOV and
// HeadOn, so that their stars are the same).
#include <memory>

#include "EOS/tabulated.hpp"
#include "TOV/cold_slice.hpp"

namespace remnant::tov {

std::unique_ptr<ColdSlice> cold_beta_slice(const eos::Tabulated<>& table);

}  // namespace remnant::tov
