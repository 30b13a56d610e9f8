#pragma once
// The uniform block grid: equal blocks covering a Cartesian box, ordered along a Morton curve and
// split into contiguous chunks over the ranks. Refinement levels and curvilinear coordinates come
// later; they extend BlockLayout (levels), the exchange plan (coarse/fine neighbours) and
// Block::cell_volume (sqrt(f)).
#include <mpi.h>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "remnant/grid.hpp"

namespace remnant::grid {

enum class Boundary { outflow, periodic, reflect };
const char* to_string(Boundary b);

// Plain settings, so that tests and tools can build a grid without a parameter database.
// Entries of the 3-arrays beyond `dimension` are ignored (that direction gets one cell, no ghosts).
struct UniformGridConfig {
  std::string coordinates = "cartesian";
  int dimension = 3;
  std::array<std::int64_t, 3> ncells{32, 32, 32};
  std::array<int, 3> block_size{16, 16, 16};
  std::array<double, 3> xmin{-1, -1, -1};
  std::array<double, 3> xmax{1, 1, 1};
  int ghost_zones = 3;
  std::array<Boundary, 3> boundary_lower{Boundary::outflow, Boundary::outflow, Boundary::outflow};
  std::array<Boundary, 3> boundary_upper{Boundary::outflow, Boundary::outflow, Boundary::outflow};
};

class BlockLayout;
class GhostExchange;

class UniformGrid final : public GridDriver {
 public:
  // Checks the settings (throws InputError) and allocates this rank's blocks.
  UniformGrid(const UniformGridConfig& config, const VariableRegistry& vars, MPI_Comm comm);
  // Reads the Grid parameters.
  explicit UniformGrid(const GridSetup& setup);
  ~UniformGrid() override;
  UniformGrid(const UniformGrid&) = delete;
  UniformGrid& operator=(const UniformGrid&) = delete;

  int dimension() const override { return config_.dimension; }
  std::span<Block* const> local_blocks() override { return block_ptrs_; }
  void synchronize(std::span<const int> groups) override;
  double reduce(int group, int comp, ReductionKind kind) override;
  std::int64_t global_cells() const override;
  double min_spacing() const override;
  std::string describe() const override;
  MPI_Comm comm() const override { return comm_; }
  CoordinateSystem coordinates() const override { return CoordinateSystem::cartesian; }
  std::vector<BlockKey> all_blocks() const override;
  void restore_blocks(std::span<const BlockKey> blocks) override;

  const UniformGridConfig& config() const { return config_; }
  const BlockLayout& layout() const { return *layout_; }

 private:
  UniformGridConfig config_;
  const VariableRegistry* vars_;
  MPI_Comm comm_;           // the caller's communicator, returned by comm()
  MPI_Comm exchange_comm_;  // a private duplicate, so ghost messages never meet other traffic
  int rank_ = 0, nranks_ = 1;
  std::unique_ptr<BlockLayout> layout_;
  std::vector<std::unique_ptr<Block>> blocks_;
  std::vector<Block*> block_ptrs_;
  std::unique_ptr<GhostExchange> exchange_;
};

}  // namespace remnant::grid
