// Table calls per recovery on the paper's rho-T plane (W = 2, b^2/2p = 1e-3, Ye = 0.1) of both shared
// tables, bounded so that a regression of the cached-Ye slice (EOS/tabulated_at_ye.hpp) or of the
// search hint is caught (counts, not timings); and the recovered states equal those of the paper's
// Brent inversion, which does not go through the slice.
#include <cstdio>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/recover.hpp"
#include "Con2Prim/state_builder.hpp"
#include "EOS/counter.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "c2p_test_util.hpp"

using namespace remnant::con2prim;
namespace eos = remnant::eos;

namespace {

struct PlaneStats {
  double calls = 0;     // mean table calls per recovery
  double evaluations = 0;  // mean master-function evaluations per recovery
  int not_ok = 0;       // status other than ok (LS220: flagged inaccurate/ambiguous in its acausal corner)
  int ambiguous = 0;
  double calls_ambiguous = 0;  // mean table calls of the ambiguous recoveries (root scans: they stop
                               // at the second state that reproduces the conserved variables)
  double worst = 0;     // largest relative difference of rho, eps, W from the Brent-inversion run
                        // (both ok, causal part of the table)
};

// n x n cell-centred samples in log rho, log T over the table; v and B fixed, antiparallel.
PlaneStats plane(const eos::Tabulated<eos::CountCalls>& e, Method m, int n) {
  Settings s;
  s.method = m;
  s.policy.W_max = 1e300;
  Settings brent = s;
  brent.eps_to_T = eos::InversionMethod::brent;
  remnant::atmosphere::Atmosphere atm;
  atm.rho_thr = 1e-300;
  const eos::Bounds& b = e.bounds();
  const Metric3 g = Metric3::flat();
  PlaneStats st;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double rho = b.rho_min * std::pow(b.rho_max / b.rho_min, (i + 0.5) / n);
      const double T = b.T_min * std::pow(b.T_max / b.T_min, (j + 0.5) / n);
      const Primitives orig = make_state(e, g, rho, T, 0.1, 2.0, 1e-3, {0.6, 0.64, 0.48}, {-0.6, -0.64, -0.48});
      Conserved c = prim_to_cons(orig, g), c2 = c;
      Primitives p, q;
      const Report rep = recover(e, s, atm, g, c, p);
      st.calls += double(rep.eos_calls);
      st.evaluations += rep.evaluations;
      st.not_ok += rep.status != Status::ok;
      if (rep.status == Status::ambiguous) ++st.ambiguous, st.calls_ambiguous += double(rep.eos_calls);
      const Report rep2 = recover(e, brent, atm, g, c2, q);
      // Where the table is acausal the conserved variables may admit several states (the two
      // inversions may then land on different ones, both accepted or flagged).
      if (rep.status != Status::ok || rep2.status != Status::ok || e.acausal(p.rho, p.ye)) continue;
      for (auto [x, y] : {std::pair{p.rho, q.rho}, {p.eps, q.eps}, {p.W, q.W}})
        st.worst = std::max(st.worst, c2p_test::rel_err(x, y));
    }
  st.calls /= n * n;
  st.evaluations /= n * n;
  if (st.ambiguous) st.calls_ambiguous /= st.ambiguous;
  return st;
}

struct Case {
  const char* table;
  Method method;
  double max_calls;  // measured (40 x 40) + a margin (Kastaun: about 4 %, Palenzuela: about 10 %)
  double max_evaluations;  // the same
  int max_not_ok;
  double max_calls_ambiguous;  // measured + about 5 %
};

}  // namespace

TEST(Con2PrimCallCounts, RhoTPlaneOfBothTablesStaysWithinItsTableCallBudget) {
  // Before the slice (issue 21): SFHo 45.4 (Kastaun) and 56.1 (Palenzuela), LS220 79.5 and 92.0 calls
  // on remnant-c2p-bench's 100 x 100 plane.
  // Brent's early stop and ln p read with ln eps at every node (issue 21, second round): SFHo
  // Kastaun 16.5 -> 13.9 calls, 5.9 -> 5.1 evaluations; bounds were 18, 28, 45, 51 calls.
  // Issue 21, goal 4 (Kastaun's analytic upper bracket end 1/(1 + qbar) and the three-point first
  // Brent step): SFHo 13.88 -> 12.61 calls, 5.12 -> 4.70 evaluations; LS220 31.78 -> 29.46 calls,
  // 5.25 -> 4.81 evaluations (this 40 x 40 plane). Bounds were 15.5 / 5.6 and 35 / 5.8; now about 4 %
  // above the new counts, below the old ones.
  // Issue 21, goal 4 (LS220's root scans): a scan stops at the second state that reproduces the
  // conserved variables (ambiguous either way), and Kastaun's jumps over stretches proven clamped by
  // rule 9: calls per ambiguous recovery 377.3 -> 281.0 (Kastaun), 301.3 -> 120.2 (Palenzuela);
  // LS220 Kastaun 29.46 -> 26.04 calls per recovery (bound was 30.6). Bounds about 5 % above.
  const Case cases[] = {{"SFHo_reduced_39r_39t_20y.h5", Method::kastaun, 13.1, 4.9, 0, 0},
                        {"SFHo_reduced_39r_39t_20y.h5", Method::palenzuela, 24.5, 9.2, 0, 0},
                        {"SRO_LS220_157r_89t_49y.h5", Method::kastaun, 27.3, 5.0, 45, 295},
                        {"SRO_LS220_157r_89t_49y.h5", Method::palenzuela, 43.5, 9.1, 45, 126}};
  for (const Case& k : cases) {
    const std::string path = c2p_test::shared_eos(k.table);
    if (!std::filesystem::exists(path)) {
      std::printf("REMNANT_TEST_SKIPPED: no table %s\n", path.c_str());
      continue;
    }
    const eos::Tabulated<eos::CountCalls> e(eos::load_table(path));
    const PlaneStats st = plane(e, k.method, 40);
    std::printf("[ %s %s ] %.2f table calls and %.2f evaluations per recovery, %d not ok (%d ambiguous, %.1f "
                "calls each), worst difference from the Brent inversion %.2e\n",
                k.table, to_string(k.method), st.calls, st.evaluations, st.not_ok, st.ambiguous,
                st.calls_ambiguous, st.worst);
    EXPECT_LE(st.calls, k.max_calls) << k.table << " " << to_string(k.method);
    EXPECT_LE(st.evaluations, k.max_evaluations) << k.table << " " << to_string(k.method);
    EXPECT_LE(st.not_ok, k.max_not_ok) << k.table << " " << to_string(k.method);
    EXPECT_LE(st.calls_ambiguous, k.max_calls_ambiguous) << k.table << " " << to_string(k.method);
    EXPECT_LT(st.worst, 1e-10) << k.table << " " << to_string(k.method);
  }
}
