#include "solve_log.hpp"

#include <cstdio>
#include <fstream>
#include <string>

#include "remnant/tsv_file.hpp"
#include "runtime.hpp"

namespace remnant::xcfc {

void write_tsv(Context& ctx, const char* reason, const XcfcStats& s, std::int64_t interval, double seconds) {
  if (ctx.rank() != 0) return;
  const std::string path = ctx.out_dir() + "/xcfc.tsv";
  Runtime& rt = runtime(ctx);
  if (!rt.tsv_started)
    start_or_resume_tsv_file(ctx, path,
                             "# iteration\ttime\treason\tX_cycles\tX_residual\tpsi_cycles\tpsi_residual\talphapsi_cycles\t"
                             "alphapsi_residual\tbeta_cycles\tbeta_residual\tupdates\tupdate_cycles\tinterval\tpsi_prediction\t"
                             "alpha_prediction\tbeta_prediction\tupdate_prediction\twall_s\n",
                             RowTime::before_step);  // a prestep row of iteration n follows n's checkpoint
  rt.tsv_started = true;
  std::ofstream out(path, std::ios::app);
  auto rel = [](const SolveStats& x) { return x.scale > 0 ? x.residual / x.scale : x.residual; };
  const PredictionError& e = rt.prediction;  // all 0 for the initial solve (nothing predicted)
  char line[640];
  std::snprintf(line, sizeof line,
                "%lld\t%.17g\t%s\t%d\t%.3e\t%d\t%.3e\t%d\t%.3e\t%d\t%.3e\t%lld\t%lld\t%lld\t%.3e\t%.3e\t%.3e\t%.3e\t%.6f\n",
                static_cast<long long>(ctx.iteration()), ctx.time(), reason, s.X.cycles(), s.X.residual(), s.psi.cycles,
                rel(s.psi), s.alpha_psi.cycles, rel(s.alpha_psi), s.beta.cycles(), s.beta.residual(),
                static_cast<long long>(rt.updates), static_cast<long long>(rt.update_cycles), static_cast<long long>(interval),
                e.psi, e.alpha, e.beta, rt.update_prediction, seconds);
  out << line;
}

void warn_unconverged(Context& ctx, const XcfcStats& s) {
  if (!(s.X.converged() && s.psi.converged && s.alpha_psi.converged && s.beta.converged()))
    ctx.warn("XCFC: a metric solve reached XCFC::max_cycles before the tolerance (see xcfc.tsv)");
}

}  // namespace remnant::xcfc
