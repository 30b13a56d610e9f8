// GRMHD benchmarks (hydro, and MHD with BM_StepMHD) on one 3D Cartesian block holding a static TOV star (octant, 40% of the
// cells inside the star at n = 32), ideal gas and the SFHo table. "zone-cycles/s" = cells x RK3 steps per
// second on one core (a step: 3 x (fluxes + divergence/sources + update + con2prim)), as Athena++
// counts them. Ghost exchange is the Grid's and not included.
//
//   bench_GRMHD                                   all benchmarks
//   bench_GRMHD --zone-cost=ideal|sfho STEPS      run STEPS steps and exit (for callgrind; see README)
//   bench_GRMHD --zone-cost=mhd-ideal|mhd-sfho STEPS   the same with the magnetic field (BM_StepMHD's)
//   bench_GRMHD --portable-kernels ...   any of these with the SSE2 kernels where the CPU has AVX2
// Both print a checksum of the conserved variables (and face fields) after the steps: a kernel
// change that is meant to keep the bits must keep it.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <utility>

#include "kernel_isa.hpp"
#include "star_block.hpp"

namespace {

using remnant::grmhd::bench::StarBlock;
namespace eos = remnant::eos;

eos::EOS make(const std::string& which) {
  eos::EosConfig c;
  if (which == "sfho") {
    c.type = "tabulated";
    c.table_file = std::string(REMNANT_SHARED_EOS_DIR) + "/SFHo_reduced_39r_39t_20y.h5";
  } else {
    c.type = "ideal_gas";
    c.gamma = 2.0;
    c.T_max = 1e6;
  }
  return eos::make_eos(c);
}

constexpr double kExtent = 12.0;  // octant edge; the star's isotropic radius is about 8.1

// The EOS, or none with the benchmark skipped and the reason shown when the table is missing
// (../shared/eos is not part of the repository).
std::optional<eos::EOS> make_or_skip(benchmark::State& st, const std::string& which) {
  try {
    return make(which);
  } catch (const eos::TableError& e) {
    st.SkipWithError(e.what());
    return std::nullopt;
  }
}

void BM_Step(benchmark::State& st, const std::string& which) {
  const int n = static_cast<int>(st.range(0));
  auto e = make_or_skip(st, which);
  if (!e) return;
  StarBlock sb(std::move(*e), n, kExtent);
  const double dt = 0.3 * kExtent / n / 0.6;
  for (auto _ : st) sb.step(dt);
  st.SetItemsProcessed(st.iterations() * sb.cells());
  st.counters["zone-cycles/s"] = benchmark::Counter(double(st.iterations() * sb.cells()), benchmark::Counter::kIsRate);
}

// The same step with the magnetic field evolved (uct_hll), and the memory of the run's groups.
void BM_StepMHD(benchmark::State& st, const std::string& which, bool magnetic) {
  const int n = static_cast<int>(st.range(0));
  auto e = make_or_skip(st, which);
  if (!e) return;
  StarBlock sb(std::move(*e), n, kExtent, magnetic);
  const double dt = 0.3 * kExtent / n / 0.6;
  for (auto _ : st) sb.step(dt);
  st.SetItemsProcessed(st.iterations() * sb.cells());
  st.counters["zone-cycles/s"] = benchmark::Counter(double(st.iterations() * sb.cells()), benchmark::Counter::kIsRate);
  st.counters["bytes/cell"] = sb.bytes_per_cell();
}

void BM_Part(benchmark::State& st, const std::string& which, int part) {
  const int n = static_cast<int>(st.range(0));
  auto e = make_or_skip(st, which);
  if (!e) return;
  StarBlock sb(std::move(*e), n, kExtent);
  for (auto _ : st) {
    if (part == 0) sb.recover();
    else if (part == 1) sb.fluxes();
    else sb.divergence();
  }
  st.SetItemsProcessed(st.iterations() * sb.cells());
}

// The parts of the MHD step (BM_StepMHD's, ideal gas): 0 the line sweeps (compute_block_fluxes_mhd), 1 the
// edge EMFs, 2 face_rhs and the flux divergence with the magnetised sources, 3 the cell-centred field and
// the recovery.
void BM_PartMHD(benchmark::State& st, int part) {
  const int n = static_cast<int>(st.range(0));
  StarBlock sb(make("ideal"), n, kExtent, true);
  for (auto _ : st) {
    if (part == 0) sb.mhd_sweeps();
    else if (part == 1) sb.mhd_emfs();
    else if (part == 2) sb.divergence();
    else sb.recover();
  }
  st.SetItemsProcessed(st.iterations() * sb.cells());
}

}  // namespace

BENCHMARK_CAPTURE(BM_PartMHD, sweeps, 0)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PartMHD, emfs, 1)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PartMHD, divergence_sources, 2)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PartMHD, cell_centred_con2prim, 3)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Step, ideal_gas, std::string("ideal"))->Arg(16)->Arg(32)->Arg(48)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Step, sfho, std::string("sfho"))->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StepMHD, hydro_ideal_gas, std::string("ideal"), false)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StepMHD, mhd_ideal_gas, std::string("ideal"), true)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StepMHD, mhd_sfho, std::string("sfho"), true)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Part, con2prim_ideal_gas, std::string("ideal"), 0)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Part, fluxes_ideal_gas, std::string("ideal"), 1)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Part, divergence_sources, std::string("ideal"), 2)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Part, con2prim_sfho, std::string("sfho"), 0)->Arg(32)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Part, fluxes_sfho, std::string("sfho"), 1)->Arg(32)->Unit(benchmark::kMicrosecond);

int main(int argc, char** argv) {
  // --portable-kernels (first argument): the SSE2 sweeps and rows even where the CPU has AVX2
  // (kernel_isa.hpp), for the figures of CPUs without it.
  if (argc > 1 && std::strcmp(argv[1], "--portable-kernels") == 0) {
    remnant::grmhd::use_portable_kernels(true);
    argv[1] = argv[0];
    ++argv, --argc;
  }
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--zone-cost=", 12) == 0) {
      std::string which = argv[i] + 12;
      const bool magnetic = which.rfind("mhd-", 0) == 0;
      if (magnetic) which = which.substr(4);
      const int steps = i + 1 < argc ? std::atoi(argv[i + 1]) : 2;
      std::optional<eos::EOS> e;
      try {
        e = make(which);
      } catch (const eos::EosError& err) {
        std::fprintf(stderr, "bench_GRMHD: %s\n", err.what());
        return 1;
      }
      StarBlock sb(std::move(*e), 32, kExtent, magnetic);
      for (int s = 0; s < steps; ++s) sb.step(0.3 * kExtent / 32 / 0.6);
      std::printf("%d steps of %lld cells (%s%s), checksum %016llx\n", steps, static_cast<long long>(sb.cells()),
                  magnetic ? "MHD, " : "", which.c_str(), static_cast<unsigned long long>(sb.checksum()));
      return 0;
    }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
