// Time per recovery (Google Benchmark): a few typical states, and the paper's rho-T plane of both
// shared tables (issue 21: <= 0.6 us per recovery), whose counters give the table calls per
// recovery. The other planes and the accuracy figures come from remnant-c2p-bench.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/recover.hpp"
#include "Con2Prim/state_builder.hpp"
#include "bench_planes.hpp"
#include "EOS/ideal_gas.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "EOS/units.hpp"

using namespace remnant::con2prim;
namespace eos = remnant::eos;

namespace {

const std::string kTable = std::string(REMNANT_SHARED_EOS_DIR) + "/SFHo_reduced_39r_39t_20y.h5";

struct Case {
  const char* name;
  double rho_cgs, T, W, b2p;
};
const Case kCases[] = {
    {"dense_cold", 5e14, 0.5, 1.2, 1e-3},
    {"disk_hot", 1e11, 5.0, 2.0, 1e-3},
    {"magnetised_fast", 1e9, 1.0, 10.0, 10.0},
};

template <class E>
void run(benchmark::State& st, const E& e, const Primitives& orig, Method m) {
  Settings s;
  s.method = m;
  s.policy.W_max = 1e300;
  remnant::atmosphere::Atmosphere atm;
  atm.rho_thr = 1e-300;
  const Metric3 g = Metric3::flat();
  const Conserved c0 = prim_to_cons(orig, g);
  for (auto _ : st) {
    Conserved c = c0;
    Primitives p;
    benchmark::DoNotOptimize(recover(e, s, atm, g, c, p));
    benchmark::DoNotOptimize(p);
  }
}

// The rho-T plane of remnant-c2p-bench's defaults (100 x 100, W = 2, b^2/2p = 1e-3, Ye = 0.1, B
// antiparallel to v): one benchmark iteration is one recovery, cycling through the plane. Counters:
// table_calls (per recovery, from one counted pass), iterations, and failures + silently wrong states.
// hint >= 0: each recovery gets the T hint T_true exp(hint u), u uniform in [-1, 1] (as the caller's
// previous T; remnant-c2p-bench --hint).
void rho_T_plane(benchmark::State& st, const std::shared_ptr<const eos::TableData>& t, Method m, double hint) {
  const eos::Tabulated<> e(t);
  const eos::Tabulated<eos::CountCalls> counted(t);
  c2p_bench::Options o;
  o.hint = hint;
  c2p_bench::Plane plane = c2p_bench::rho_T_plane(e, o);
  c2p_bench::add_hints(plane, o);
  Settings s = o.settings;
  s.method = m;
  remnant::atmosphere::Atmosphere atm;
  atm.rho_thr = o.rho_thr;
  const auto res = c2p_bench::run_counted(counted, s, atm, plane);
  const c2p_bench::Summary su = c2p_bench::summarise(res, s.accuracy);
  const Metric3 g = Metric3::flat();
  std::vector<Conserved> cons;
  for (const auto& pt : plane.points) cons.push_back(prim_to_cons(pt.orig, g));
  std::size_t i = 0;
  for (auto _ : st) {
    Conserved c = cons[i];
    const double T_hint = plane.points[i].T_hint;
    if (++i == cons.size()) i = 0;
    Primitives p;
    benchmark::DoNotOptimize(recover(e, s, atm, g, c, p, T_hint));
    benchmark::DoNotOptimize(p);
  }
  st.counters["table_calls"] = su.mean_eos_calls;
  st.counters["iter"] = su.mean_iterations;
  st.counters["bad"] = double(su.failures + su.silently_wrong + su.nan);
  st.counters["max_eps_recov"] = su.max_eps_recov;
}

void register_planes() {
  for (const char* name : {"SFHo_reduced_39r_39t_20y", "SRO_LS220_157r_89t_49y"}) {
    const std::string path = std::string(REMNANT_SHARED_EOS_DIR) + "/" + name + ".h5";
    if (!std::filesystem::exists(path)) continue;
    const auto t = eos::load_table(path);
    for (Method m : {Method::kastaun, Method::palenzuela}) {
      benchmark::RegisterBenchmark((std::string("rhoT_plane/") + name + "/" + to_string(m)).c_str(),
                                   [t, m](benchmark::State& st) { rho_T_plane(st, t, m, -1); });
      benchmark::RegisterBenchmark((std::string("rhoT_plane_hint5pc/") + name + "/" + to_string(m)).c_str(),
                                   [t, m](benchmark::State& st) { rho_T_plane(st, t, m, 0.05); });
    }
  }
}

void register_all() {
  register_planes();
  static std::shared_ptr<eos::Tabulated<>> table;
  static eos::IdealGas<> gas(5.0 / 3.0);
  if (std::filesystem::exists(kTable)) table = std::make_shared<eos::Tabulated<>>(eos::load_table(kTable));
  for (const Case& k : kCases)
    for (Method m : {Method::kastaun, Method::palenzuela}) {
      const std::string suffix = std::string(k.name) + "/" + to_string(m);
      const double rho = k.rho_cgs * remnant::units::rho_cgs_to_code;
      if (table) {
        const Primitives p = make_state(*table, Metric3::flat(), rho, k.T, 0.1, k.W, k.b2p, {1, 0.5, 0.2}, {-0.3, 1, 0});
        benchmark::RegisterBenchmark(("tabulated/" + suffix).c_str(),
                                     [p, m](benchmark::State& st) { run(st, *table, p, m); });
      }
      const Primitives q = make_state(gas, Metric3::flat(), rho, k.T, 0.1, k.W, k.b2p, {1, 0.5, 0.2}, {-0.3, 1, 0});
      benchmark::RegisterBenchmark(("ideal_gas/" + suffix).c_str(), [q, m](benchmark::State& st) { run(st, gas, q, m); });
    }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
