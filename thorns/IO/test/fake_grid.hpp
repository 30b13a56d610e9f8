#pragma once
// A minimal GridDriver for IO tests: a 1D/2D/3D box of equal blocks in any coordinate system,
// blocks dealt to the ranks in contiguous gid ranges. It exists so that IO's curvilinear and
// multi-block paths can be tested without the Grid thorn.
#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include "remnant/grid.hpp"

namespace remnant::io::test {

class FakeGrid final : public GridDriver {
 public:
  FakeGrid(const VariableRegistry& vars, CoordinateSystem c, int dim, std::array<int, 3> nblocks, std::array<int, 3> n,
           std::array<double, 3> lo, std::array<double, 3> hi, MPI_Comm comm)
      : coords_(c), dim_(dim), comm_(comm) {
    int rank = 0, nranks = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &nranks);
    std::array<double, 3> dx{};
    for (int d = 0; d < 3; ++d) dx[d] = (hi[d] - lo[d]) / (nblocks[d] * n[d]);
    const std::int64_t total = std::int64_t{nblocks[0]} * nblocks[1] * nblocks[2];
    std::int64_t gid = 0;
    for (int k = 0; k < nblocks[2]; ++k)
      for (int j = 0; j < nblocks[1]; ++j)
        for (int i = 0; i < nblocks[0]; ++i, ++gid) {
          keys_.push_back(BlockKey{0, {i, j, k}});
          if (gid * nranks / total != rank) continue;
          std::array<double, 3> blo{lo[0] + i * n[0] * dx[0], lo[1] + j * n[1] * dx[1], lo[2] + k * n[2] * dx[2]};
          std::array<int, 3> ng{};
          for (int d = 0; d < dim; ++d) ng[d] = 1;
          blocks_.push_back(std::make_unique<Block>(gid, 0, std::array<std::int64_t, 3>{i, j, k}, n, ng, blo, dx, vars));
          ptrs_.push_back(blocks_.back().get());
        }
  }
  int dimension() const override { return dim_; }
  std::span<Block* const> local_blocks() override { return ptrs_; }
  void synchronize(std::span<const int>) override {}
  double reduce(int, int, ReductionKind) override { return 0; }
  std::int64_t global_cells() const override { return 0; }
  double min_spacing() const override { return 0; }
  std::string describe() const override { return "fake"; }
  MPI_Comm comm() const override { return comm_; }
  CoordinateSystem coordinates() const override { return coords_; }
  std::vector<BlockKey> all_blocks() const override { return keys_; }
  void restore_blocks(std::span<const BlockKey>) override {}

 private:
  CoordinateSystem coords_;
  int dim_;
  MPI_Comm comm_;
  std::vector<BlockKey> keys_;
  std::vector<std::unique_ptr<Block>> blocks_;
  std::vector<Block*> ptrs_;
};

// A registry with one cell-centred scalar group Test::f.
inline VariableRegistry one_scalar_registry() {
  VariableRegistry vars;
  VariableGroupSpec g;
  g.thorn = "Test";
  g.name = "f";
  g.components = expand_tensor(TensorKind::scalar, "f");
  g.role = VariableRole::evolved;
  g.checkpoint = true;
  vars.add(g);
  return vars;
}

}  // namespace remnant::io::test
