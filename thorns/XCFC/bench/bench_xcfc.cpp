// Cost of xCFC solves of a BU0 star on the BU0-dyn grid (1D spherical 640 cells to r = 60) and the
// migration grid (2D spherical 640 x 32): a cold solve (full multigrid, tolerance 1e-10) and a
// warm-started evolution solve (tolerance 1e-6) after the matter changed by 1e-5 relative. The
// counters give V-cycles per solve. Compare with one RK3 step of GRMHD on the same grid from the
// run timers (README.md, "Benchmarks").
#include <benchmark/benchmark.h>

#include <cmath>

#include "TOV/tov_solver.hpp"
#include "XCFC/xcfc_system.hpp"
#include "remnant/heap_reuse.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;

// 1D: the BU0-dyn grid; 2D: the migration grid; 3D: spherical 128 x 16 x 32 over the same r and
// theta ranges, phi periodic.
GridShape grid(int dim) {
  GridShape s;
  s.coordinates = CoordinateSystem::spherical;
  s.dimension = dim;
  s.n = dim == 3 ? std::array<int, 3>{128, 16, 32} : std::array<int, 3>{640, dim == 2 ? 32 : 1, 1};
  s.lo = {0, 0, 0};
  s.dx = {60.0 / s.n[0], (dim >= 2 ? 1.5707963267948966 : 3.141592653589793) / s.n[1], 6.283185307179586 / s.n[2]};
  const Boundary phi = dim == 3 ? Boundary::periodic : Boundary::outer;
  s.boundary = {{{Boundary::origin, Boundary::outer},
                 {Boundary::axis, dim >= 2 ? Boundary::reflect : Boundary::axis},
                 {phi, phi}}};
  return s;
}

// Uniform grids: composite fields of one part.
struct Star {
  CompositeField E, p;
  VectorField S;
  explicit Star(const GridShape& s) {
    const auto slice = tov::polytrope_slice(100.0, 2.0, 0.5);
    const tov::TovStar star(*slice, 1.28e-3);
    E.part.assign(1, std::vector<double>(s.cells())), p = E;
    for (auto& c : S) c.part.assign(1, std::vector<double>(s.cells(), 0.0));
    std::size_t q = 0;
    for (int k = 0; k < s.n[2]; ++k)
      for (int j = 0; j < s.n[1]; ++j)
        for (int i = 0; i < s.n[0]; ++i, ++q) {
          const tov::TovPoint t = star.at(s.centre(0, i));
          E.part[0][q] = std::pow(t.psi, 6) * t.rho * (1 + t.eps);
          p.part[0][q] = t.press;
          S[0].part[0][q] = 1e-8 * E.part[0][q] * std::sin(0.3 * s.centre(0, i));  // a small radial momentum
        }
  }
};

void solve_all(XcfcSolver& sv, const Star& m, XcfcState& st, const SolveSettings& set, XcfcStats& stats) {
  sv.solve_conformal_factor(m.E, m.S, st, stats, set);
  CompositeField Str = m.p;
  for (std::size_t q = 0; q < Str.part[0].size(); ++q) Str.part[0][q] = 3 * std::pow(st.psi.part[0][q], 6) * m.p.part[0][q];
  sv.solve_lapse_and_shift(m.E, m.S, Str, st, stats, set);
}

void count(benchmark::State& state, const XcfcStats& s) {
  state.counters["Vcycles_X"] = s.X.cycles();
  state.counters["Vcycles_psi"] = s.psi.cycles;
  state.counters["Vcycles_alphapsi"] = s.alpha_psi.cycles;
  state.counters["Vcycles_beta"] = s.beta.cycles();
}

// The star on the grid of a dimension, its solver and the settings of a cold (initial) solve.
struct Problem {
  GridShape s;
  XcfcSolver sv;
  Star m;
  SolveSettings set;
  XcfcStats stats;
  explicit Problem(int dim) : s(grid(dim)), sv(s), m(s) {
    set.tolerance = 1e-10;
    set.full_multigrid = true;
  }
};

void BM_ColdSolve(benchmark::State& state) {
  Problem P(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    XcfcState st;
    solve_all(P.sv, P.m, st, P.set, P.stats);
  }
  count(state, P.stats);
}

void BM_WarmSolve(benchmark::State& state) {
  Problem P(static_cast<int>(state.range(0)));
  auto& [s, sv, m, set, stats] = P;
  XcfcState base;
  solve_all(sv, m, base, set, stats);
  set.tolerance = 1e-6;
  set.full_multigrid = false;
  int step = 0;
  for (auto _ : state) {
    state.PauseTiming();
    XcfcState st = base;
    const double f = 1 + 1e-5 * std::sin(0.1 * ++step);
    Star mm = m;
    for (auto& e : mm.E.part[0]) e *= f;
    state.ResumeTiming();
    solve_all(sv, mm, st, set, stats);
  }
  count(state, stats);
}

// One V-cycle of the psi (range 1 = 1) or the alpha psi equation (0) from the converged solution
// with perturbed sources: the cost unit of the solves above.
void BM_VCycle(benchmark::State& state) {
  Problem P(static_cast<int>(state.range(0)));
  auto& [s, sv, m, set, stats] = P;
  XcfcState st;
  solve_all(sv, m, st, set, stats);
  ScalarEquation eq = state.range(1) ? conformal_factor_equation() : lapse_equation();
  if (state.range(1)) eq.s1.resize(s.cells()), eq.s7.assign(s.cells(), 0.0);
  else eq.k.resize(s.cells());
  for (std::size_t q = 0; q < s.cells(); ++q) {
    const double E = m.E.part[0][q], psi = st.psi.part[0][q];
    if (state.range(1)) eq.s1[q] = -2 * 3.141592653589793 * E * 1.00001;
    else eq.k[q] = 2 * 3.141592653589793 * E * 1.00001 / (psi * psi);
  }
  set.tolerance = 1e-30;
  set.max_cycles = 1;
  set.full_multigrid = false;
  set.direct_1d = false;
  std::vector<double> u = state.range(1) ? st.psi.part[0] : st.alpha_psi.part[0];
  for (auto _ : state) {
    std::vector<double> w = u;
    benchmark::DoNotOptimize(sv.multigrid().base().solve(eq, w, set));
  }
}

}  // namespace

// The heap as the executable sets it at start-up (run_main), before the first solve.
const bool heap_set = (remnant::keep_freed_memory_for_reuse(), true);

BENCHMARK(BM_VCycle)->Args({1, 0})->Args({1, 1})->Args({2, 0})->Args({2, 1})->Args({3, 0})->Args({3, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ColdSolve)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WarmSolve)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
