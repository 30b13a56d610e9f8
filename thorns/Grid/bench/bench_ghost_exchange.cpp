// Ghost exchange plus outer boundaries of one 5-component cell-centred group; items are interior
// cells of the whole grid per synchronisation (ns per cell = 1e9 / items_per_second).
// Arguments: cells per direction, block size. Periodic (all exchange) and outflow (exchange on the
// inside, boundary fill on the faces).
#include <benchmark/benchmark.h>
#include <mpi.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "Grid/uniform_grid.hpp"

namespace {

using remnant::grid::Boundary;
using remnant::grid::UniformGrid;
using remnant::grid::UniformGridConfig;

void run(benchmark::State& state, Boundary bc) {
  UniformGridConfig c;
  const auto n = state.range(0);
  const auto bs = static_cast<int>(state.range(1));
  c.ncells = {n, n, n};
  c.block_size = {bs, bs, bs};
  c.ghost_zones = 3;
  c.boundary_lower = c.boundary_upper = {bc, bc, bc};
  remnant::VariableRegistry vars;
  remnant::VariableGroupSpec g;
  g.thorn = "Bench";
  g.name = "cons";
  // D, S_i, tau: the conserved hydro variables.
  for (auto [kind, name] : {std::pair{remnant::TensorKind::scalar, "D"},
                            std::pair{remnant::TensorKind::covector, "S"},
                            std::pair{remnant::TensorKind::scalar, "tau"}})
    for (auto& comp : remnant::expand_tensor(kind, name)) g.components.push_back(comp);
  const int id = vars.add(g);
  UniformGrid grid(c, vars, MPI_COMM_WORLD);
  for (remnant::Block* b : grid.local_blocks())
    for (std::size_t p = 0; p < b->size(id); ++p) b->data(id)[p] = static_cast<double>(p % 97);
  const std::vector<int> groups = {id};
  for (auto _ : state) {
    grid.synchronize(groups);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * grid.global_cells());
  state.counters["blocks"] = static_cast<double>(grid.local_blocks().size());
}

// On several ranks every rank must run the same number of (collective) synchronisations, so the
// iteration count is fixed instead of chosen by each rank's own clock.
void register_benchmarks(int nranks) {
  auto add = [nranks](const char* name, Boundary bc, std::vector<std::vector<std::int64_t>> args) {
    auto* b = benchmark::RegisterBenchmark(name, [bc](benchmark::State& s) { run(s, bc); });
    for (const auto& a : args) b->Args(a);
    b->Unit(benchmark::kMicrosecond);
    if (nranks > 1) b->Iterations(100);
  };
  add("BM_GhostExchangePeriodic", Boundary::periodic, {{64, 16}, {64, 32}, {128, 16}});
  add("BM_GhostExchangeOutflow", Boundary::outflow, {{64, 16}});
}

// Keeps the other ranks quiet.
class SilentReporter : public benchmark::BenchmarkReporter {
 public:
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>&) override {}
};

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  benchmark::Initialize(&argc, argv);
  int rank = 0, nranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  register_benchmarks(nranks);
  // Only rank 0 reports; the others run the same iterations silently.
  if (rank != 0) {
    SilentReporter silent;
    benchmark::RunSpecifiedBenchmarks(&silent);
  } else {
    benchmark::RunSpecifiedBenchmarks();
  }
  benchmark::Shutdown();
  MPI_Finalize();
  return 0;
}
