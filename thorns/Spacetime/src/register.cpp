// Spacetime: the flat initial metric (initial-data thorns overwrite it).
#include <algorithm>

#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::spacetime {
namespace {

void init_flat(Context& ctx) {
  using Metric = vars::Spacetime::metric;
  for (Block* b : ctx.grid().local_blocks()) {
    const Metric metric(ctx, *b);
    const std::size_t n = b->points_per_component(metric.group());
    for (int c = 0; c < Metric::ncomp; ++c) {
      const bool one = c == Metric::idx::psi || c == Metric::idx::alpha;  // everywhere, ghosts too
      std::fill_n(b->data(metric.group()) + static_cast<std::size_t>(c) * n, n, one ? 1.0 : 0.0);
    }
  }
}

}  // namespace
}  // namespace remnant::spacetime

REMNANT_REGISTER_THORN(Spacetime) { reg.function("Spacetime_InitFlat", remnant::spacetime::init_flat); }
