// IO: TSV time series of reductions (HDF5 output and checkpoints come with the IO issue).
#include <memory>

#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "tsv_output.hpp"

namespace remnant::io {
namespace {

struct State {
  std::vector<TsvSeries> series;
  bool started = false;
};

State& state(Context& ctx) {
  if (!ctx.has_service("IO::state")) ctx.publish("IO::state", std::make_shared<State>());
  return ctx.service<State>("IO::state");
}

void check_tsv(Context& ctx) {
  state(ctx).series = plan_tsv_series(ctx, ctx.param<std::vector<std::string>>("IO", "tsv_variables"),
                                      ctx.param<std::vector<std::string>>("IO", "tsv_reductions"));
}

void write_tsv(Context& ctx) {
  const auto every = ctx.param<std::int64_t>("IO", "tsv_every");
  if (every <= 0 || ctx.iteration() % every != 0) return;
  State& s = state(ctx);
  if (!s.started) {
    start_tsv_files(s.series, ctx);
    s.started = true;
  }
  append_tsv_lines(s.series, ctx);
}

}  // namespace
}  // namespace remnant::io

REMNANT_REGISTER_THORN(IO) {
  reg.function("IO_CheckTSV", remnant::io::check_tsv);
  reg.function("IO_WriteTSV", remnant::io::write_tsv);
}
