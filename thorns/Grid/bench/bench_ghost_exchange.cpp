// Ghost exchange plus outer boundaries of one 5-component cell-centred group, per interior cell.
// Arguments: cells per direction, block size. Periodic (all exchange) and outflow (exchange on the
// inside, boundary fill on the faces).
#include <benchmark/benchmark.h>
#include <mpi.h>

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

void BM_GhostExchangePeriodic(benchmark::State& state) { run(state, Boundary::periodic); }
void BM_GhostExchangeOutflow(benchmark::State& state) { run(state, Boundary::outflow); }

BENCHMARK(BM_GhostExchangePeriodic)->Args({64, 16})->Args({64, 32})->Args({128, 16})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GhostExchangeOutflow)->Args({64, 16})->Unit(benchmark::kMicrosecond);

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
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
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
