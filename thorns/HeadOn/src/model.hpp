#pragma once
// The isolated star of the HeadOn parameters (its cold slice and TOV solution), built once and
// shared by the scheduled functions as service "HeadOn::model".
#include <memory>

#include "HeadOn/binary.hpp"
#include "TOV/cold_slice.hpp"
#include "TOV/tov_solver.hpp"
#include "remnant/context.hpp"

namespace remnant::headon {

struct Model {
  std::unique_ptr<tov::ColdSlice> slice;
  std::unique_ptr<tov::TovStar> star;
  std::unique_ptr<Binary> binary;
};

// Builds the model on the first call (throws std::exception for a star that does not exist).
const Model& model(Context& ctx);
// The slice alone (for the parameter checks, before the model is needed).
std::unique_ptr<tov::ColdSlice> slice_from_parameters(const Context& ctx);

}  // namespace remnant::headon
