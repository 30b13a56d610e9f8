// Ghost exchange plus outer boundaries of one 5-component cell-centred group, and regrids; items
// are interior cells of the whole grid per synchronisation or regrid (ns per cell = 1e9 /
// items_per_second). Uniform: cells per direction and block size, periodic (all exchange) and
// outflow. Refined: a 3D Cartesian mesh with nested boxes (levels 0-2), and a 2D spherical mesh
// with the paper's shell/core layout. Regrid: refine and derefine a box alternately (every
// variable synchronised, prolonged or restricted, blocks rebalanced).
#include <benchmark/benchmark.h>
#include <mpi.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "Grid/amr_grid.hpp"
#include "remnant/error.hpp"

namespace {

using remnant::grid::Boundary;
using remnant::grid::AmrGrid;
using remnant::grid::GridConfig;

void run(benchmark::State& state, Boundary bc) {
  GridConfig c;
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
  AmrGrid grid(c, vars, MPI_COMM_WORLD);
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

remnant::VariableRegistry hydro_registry(int& id) {
  remnant::VariableRegistry vars;
  remnant::VariableGroupSpec g;
  g.thorn = "Bench";
  g.name = "cons";
  g.role = remnant::VariableRole::evolved;
  for (auto [kind, name] : {std::pair{remnant::TensorKind::scalar, "D"}, std::pair{remnant::TensorKind::covector, "S"},
                            std::pair{remnant::TensorKind::scalar, "tau"}})
    for (auto& comp : remnant::expand_tensor(kind, name)) g.components.push_back(comp);
  id = vars.add(g);
  return vars;
}

GridConfig nested_boxes(std::int64_t n) {
  GridConfig c;
  c.ncells = {n, n, n};
  c.block_size = {16, 16, 16};
  c.max_level = 2;
  c.regions = {{remnant::grid::RegionKind::box, remnant::grid::RegionMode::at_least, 1, {-0.5, 0.5, -0.5, 0.5, -0.5, 0.5}},
               {remnant::grid::RegionKind::box, remnant::grid::RegionMode::at_least, 2, {-0.2, 0.2, -0.2, 0.2, -0.2, 0.2}}};
  return c;
}

GridConfig spherical_core(std::int64_t n) {
  GridConfig c;
  c.coordinates = remnant::CoordinateSystem::spherical;
  c.dimension = 2;
  c.ncells = {n, n / 2, 1};
  c.block_size = {16, 16, 1};
  c.xmin = {0, 0, 0};
  c.xmax = {100, 1.5707963267948966, 1};
  c.boundary_lower = {Boundary::origin, Boundary::axis, Boundary::outflow};
  c.boundary_upper = {Boundary::outflow, Boundary::reflect, Boundary::outflow};
  c.max_level = 2;
  c.regions = {{remnant::grid::RegionKind::shell, remnant::grid::RegionMode::at_least, 2, {12.5, 30, 0, 0, 0, 0}},
               {remnant::grid::RegionKind::sphere, remnant::grid::RegionMode::at_most, 1, {0, 12.5, 0, 0, 0, 0}}};
  return c;
}

void fill(AmrGrid& grid, int id) {
  for (remnant::Block* b : grid.local_blocks())
    for (std::size_t p = 0; p < b->size(id); ++p) b->data(id)[p] = 1.0 + static_cast<double>(p % 97);
}

void run_refined(benchmark::State& state, const GridConfig& c) {
  int id = 0;
  const remnant::VariableRegistry vars = hydro_registry(id);
  AmrGrid grid(c, vars, MPI_COMM_WORLD);
  fill(grid, id);
  const std::vector<int> groups = {id};
  for (auto _ : state) {
    grid.synchronize(groups);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * grid.global_cells());
  state.counters["blocks"] = static_cast<double>(grid.all_blocks().size());
  state.counters["levels"] = grid.finest_level() + 1;
}

void run_regrid(benchmark::State& state) {
  int id = 0;
  const remnant::VariableRegistry vars = hydro_registry(id);
  AmrGrid grid(nested_boxes(state.range(0)), vars, MPI_COMM_WORLD);
  fill(grid, id);
  // A criterion that alternately asks for one more level in the lower half (z < 0) and for
  // coarsening there; the static boxes keep their levels.
  bool up = true;
  grid.add_refinement_criterion("bench", [&up](remnant::Block& b) { return b.lo[2] < 0 ? (up ? 1 : -1) : 0; });
  double cells = 0;
  for (auto _ : state) {
    grid.regrid();
    cells += static_cast<double>(grid.global_cells());
    up = !up;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(cells));
  state.counters["blocks"] = static_cast<double>(grid.all_blocks().size());
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
  auto fixed = [nranks](benchmark::internal::Benchmark* b) {
    b->Unit(benchmark::kMicrosecond);
    if (nranks > 1) b->Iterations(20);
  };
  fixed(benchmark::RegisterBenchmark("BM_GhostExchangeNestedBoxes3D", [](benchmark::State& s) {
          run_refined(s, nested_boxes(s.range(0)));
        })->Arg(64));
  fixed(benchmark::RegisterBenchmark("BM_GhostExchangeSphericalCore2D", [](benchmark::State& s) {
          run_refined(s, spherical_core(s.range(0)));
        })->Arg(256));
  fixed(benchmark::RegisterBenchmark("BM_RegridNestedBoxes3D", run_regrid)->Arg(64));
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
