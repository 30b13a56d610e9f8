// Time per recovery for a few typical states (Google Benchmark). The whole-plane figures and EOS
// call counts come from remnant-c2p-bench; this tracks the kernel's speed in CI-sized runs.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/recover.hpp"
#include "Con2Prim/state_builder.hpp"
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

void register_all() {
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
