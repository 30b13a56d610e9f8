#pragma once
// The Grid thorn's mesh: a forest of equal blocks at refinement levels in 2:1 balance, in
// Cartesian, cylindrical or spherical coordinates, ordered along a Morton curve and split into
// contiguous chunks over the ranks (rebalanced at every regrid). One global time step (no
// subcycling). See thorns/Grid/README.md.
#include <mpi.h>

#include <map>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "Grid/grid_config.hpp"
#include "remnant/grid.hpp"

namespace remnant::grid {

class Forest;
class BoundaryMaps;
class LevelGeometry;
class GhostExchange;
class FluxCorrection;
class EdgeCorrection;
struct FaceVector;

class AmrGrid final : public GridDriver {
 public:
  // Checks the settings (throws InputError), builds the static refinement layout and allocates
  // this rank's blocks.
  AmrGrid(const GridConfig& config, const VariableRegistry& vars, MPI_Comm comm);
  // Reads the Grid parameters.
  explicit AmrGrid(const GridSetup& setup);
  ~AmrGrid() override;
  AmrGrid(const AmrGrid&) = delete;
  AmrGrid& operator=(const AmrGrid&) = delete;

  int dimension() const override { return config_.dimension; }
  std::span<Block* const> local_blocks() override { return block_ptrs_; }
  void synchronize(std::span<const int> groups) override;
  double reduce(int group, int comp, ReductionKind kind) override;
  std::int64_t global_cells() const override;
  double min_spacing() const override { return min_spacing_; }
  std::string describe() const override;
  MPI_Comm comm() const override { return comm_; }
  CoordinateSystem coordinates() const override { return config_.coordinates; }
  Domain domain() const override;
  std::vector<BlockKey> all_blocks() const override;
  void restore_blocks(std::span<const BlockKey> blocks) override;
  void correct_fluxes(std::span<const int> face_groups) override;
  void correct_edges(std::span<const int> edge_groups) override;
  void add_refinement_criterion(const std::string& name, RefinementCriterion fn) override;
  void add_outflow_condition(int group, OutflowCondition fn) override;

  // One adaptive regrid: synchronises every variable, evaluates the criteria (Löhner on
  // Grid::refine_variable and the thorns' criteria) and the static regions, refines or coarsens
  // by at most one level, moves the data (prolongation, restriction, rebalancing along the
  // curve). Returns whether the mesh changed. Collective. The caller invalidates ghosts and runs
  // post_regrid.
  bool regrid();
  // Replaces the mesh by these leaves (any order), moving the data; for tests and tools.
  bool set_leaves(std::vector<BlockKey> leaves);

  const GridConfig& config() const { return config_; }
  const Forest& forest() const { return *forest_; }
  int finest_level() const;
  // Refinement wishes of the last regrid per local block (for tests and diagnostics).
  const std::vector<int>& last_wishes() const { return last_wishes_; }

 private:
  std::unique_ptr<Block> make_block(std::int64_t gid, const BlockKey& key) const;
  void install(std::unique_ptr<Forest> forest, std::vector<std::unique_ptr<Block>> blocks);
  GhostExchange& exchange_for(const std::array<int, 3>& stagger);
  double compute_min_spacing() const;
  std::vector<int> gather_wishes(const std::vector<int>& local) const;
  void synchronize_all();
  bool move_to(std::vector<BlockKey> leaves);

  GridConfig config_;
  const VariableRegistry* vars_;
  MPI_Comm comm_;           // the caller's communicator, returned by comm()
  MPI_Comm exchange_comm_;  // a private duplicate, so ghost messages never meet other traffic
  int rank_ = 0, nranks_ = 1;
  std::unique_ptr<BoundaryMaps> maps_;
  std::unique_ptr<LevelGeometry> geometry_;
  std::unique_ptr<Forest> forest_;
  std::vector<std::unique_ptr<Block>> blocks_;
  std::vector<Block*> block_ptrs_;
  std::map<std::array<int, 3>, std::unique_ptr<GhostExchange>> exchanges_;
  std::unique_ptr<FluxCorrection> flux_;
  std::map<std::array<int, 3>, std::unique_ptr<EdgeCorrection>> edges_;
  std::vector<std::pair<std::string, RefinementCriterion>> criteria_;
  std::map<int, std::vector<OutflowCondition>> outflow_conditions_;  // per group, in the order added
  int refine_group_ = -1, refine_comp_ = 0;
  double min_spacing_ = 0;
  std::vector<int> last_wishes_;
  std::vector<FaceVector> face_vectors_;  // divergence-preserving face groups
};

}  // namespace remnant::grid
