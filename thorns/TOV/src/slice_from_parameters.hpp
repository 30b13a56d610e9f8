#pragma once
// The cold EOS slice the TOV parameters ask for (shared by the parameter checks and the initial data).
#include <memory>

#include "TOV/cold_slice.hpp"
#include "remnant/context.hpp"

namespace remnant::tov {

std::unique_ptr<ColdSlice> slice_from_parameters(const Context& ctx);

// The densities the slice covers: the EOS's validity range (a table's range for tabulated_beta).
struct DensityRange {
  double min = 0, max = 0;
  const char* source = "";  // which parameters set it, for error messages
};
DensityRange slice_density_range(const Context& ctx);

}  // namespace remnant::tov
