// EOS micro-benchmarks: table evaluations per second, eps -> T inversions per second and the
// mean number of table evaluations per inversion (counter "evals/inv"). Tables are read from
// REMNANT_SHARED_EOS_DIR; a missing table skips its benchmarks with a message.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>

#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"

using namespace remnant::eos;

namespace {

std::string table_path(const std::string& name) { return std::string(REMNANT_SHARED_EOS_DIR) + "/" + name; }
const char* kTables[] = {"SFHo_reduced_39r_39t_20y.h5", "SRO_LS220_157r_89t_49y.h5"};

std::shared_ptr<const TableData> table(int which) {
  static std::map<int, std::shared_ptr<const TableData>> cache;
  auto& t = cache[which];
  if (!t && std::filesystem::exists(table_path(kTables[which]))) t = load_table(table_path(kTables[which]));
  return t;
}

struct Point {
  double rho, T, ye, eps;
};

// Random states, log-uniform in rho and T inside the table, with their eps.
std::vector<Point> points(const Tabulated<>& eos, std::size_t n) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const Bounds& b = eos.bounds();
  std::vector<Point> v(n);
  for (auto& p : v) {
    p.rho = b.rho_min * std::pow(b.rho_max / b.rho_min, u(rng));
    p.T = b.T_min * std::pow(b.T_max / b.T_min, u(rng));
    p.ye = b.ye_min + (b.ye_max - b.ye_min) * u(rng);
    p.eps = eos.eps(p.rho, p.T, p.ye);
  }
  return v;
}

// One EOS call per iteration, eval(eos, point), over the random states of table state.range(0).
template <class Eval>
void bench_pointwise(benchmark::State& state, Eval eval) {
  auto t = table(int(state.range(0)));
  if (!t) return state.SkipWithError("table not found");
  Tabulated<> eos(t);
  const auto pts = points(eos, 4096);
  std::size_t i = 0;
  for (auto _ : state) {
    const Point& p = pts[i++ & 4095];
    benchmark::DoNotOptimize(eval(eos, p));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(kTables[state.range(0)]);
}

void BM_Thermo(benchmark::State& state) {
  bench_pointwise(state, [](const Tabulated<>& eos, const Point& p) { return eos.thermo(p.rho, p.T, p.ye); });
}
BENCHMARK(BM_Thermo)->Arg(0)->Arg(1);

void BM_Press(benchmark::State& state) {
  bench_pointwise(state, [](const Tabulated<>& eos, const Point& p) { return eos.press(p.rho, p.T, p.ye); });
}
BENCHMARK(BM_Press)->Arg(0)->Arg(1);

// Args: table, method (0 exact, 1 Brent), guess (0 none, 1 T within 5 percent).
void BM_EpsToT(benchmark::State& state) {
  auto t = table(int(state.range(0)));
  if (!t) return state.SkipWithError("table not found");
  Tabulated<> plain(t);
  Tabulated<CountCalls> eos(t);
  const auto pts = points(plain, 4096);
  const InversionMethod m = state.range(1) ? InversionMethod::brent : InversionMethod::exact;
  const bool guess = state.range(2) != 0;
  std::size_t i = 0;
  for (auto _ : state) {
    const Point& p = pts[i++ & 4095];
    benchmark::DoNotOptimize(eos.temperature(p.rho, p.eps, p.ye, guess ? p.T * 1.05 : 0.0, m));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["evals/inv"] = double(eos.counter().count()) / double(state.iterations());
  state.SetLabel(std::string(kTables[state.range(0)]) + (m == InversionMethod::exact ? " exact" : " brent") +
                 (guess ? " +guess" : ""));
}
BENCHMARK(BM_EpsToT)->ArgsProduct({{0, 1}, {0, 1}, {0, 1}});

// The counting policy must cost nothing when off: the same evaluation with CountCalls.
void BM_ThermoCounted(benchmark::State& state) {
  auto t = table(0);
  if (!t) return state.SkipWithError("table not found");
  Tabulated<CountCalls> eos(t);
  const auto pts = points(Tabulated<>(t), 4096);
  std::size_t i = 0;
  for (auto _ : state) {
    const Point& p = pts[i++ & 4095];
    benchmark::DoNotOptimize(eos.thermo(p.rho, p.T, p.ye));
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["evals/call"] = double(eos.counter().count()) / double(state.iterations());
}
BENCHMARK(BM_ThermoCounted);

}  // namespace

BENCHMARK_MAIN();
