// Spacetime: the flat initial metric (initial-data thorns overwrite it).
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"

namespace remnant::spacetime {
namespace {

void init_flat(Context& ctx) {
  const int metric = ctx.var("Spacetime::metric");
  for (Block* b : ctx.grid().local_blocks()) {
    double* p = b->data(metric);
    const std::size_t n = b->points_per_component(metric);
    for (int c = 0; c < 5; ++c)
      for (std::size_t i = 0; i < n; ++i) p[static_cast<std::size_t>(c) * n + i] = c < 2 ? 1.0 : 0.0;
  }
}

}  // namespace
}  // namespace remnant::spacetime

REMNANT_REGISTER_THORN(Spacetime) { reg.function("Spacetime_InitFlat", remnant::spacetime::init_flat); }
