#include "Grid/amr_grid.hpp"

#include <algorithm>
#include <cmath>

#include "boundary_map.hpp"
#include "config.hpp"
#include "edge_correction.hpp"
#include "face_vector.hpp"
#include "flux_correction.hpp"
#include "forest.hpp"
#include "ghost_exchange.hpp"
#include "level_geometry.hpp"
#include "lohner.hpp"
#include "memory_estimate.hpp"
#include "outer_boundary.hpp"
#include "reduction.hpp"
#include "refinement.hpp"
#include "regrid.hpp"
#include "remnant/error.hpp"
#include "transfer.hpp"

namespace remnant::grid {

AmrGrid::AmrGrid(const GridConfig& config, const VariableRegistry& vars, MPI_Comm comm)
    : config_(checked(config)), vars_(&vars), comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &nranks_);
  MPI_Comm_dup(comm, &exchange_comm_);
  face_vectors_ = find_face_vectors(vars, config_.dimension);
  maps_ = std::make_unique<BoundaryMaps>(config_);
  geometry_ = std::make_unique<LevelGeometry>(config_, config_.max_level);
  if (!config_.refine_variable.empty()) {
    const std::string& v = config_.refine_variable;
    const auto dot = v.find('.');
    refine_group_ = vars.find(v.substr(0, dot));
    if (refine_group_ < 0)
      throw InputError({"Grid::refine_variable", 0, 0}, "Grid::refine_variable = " + v + ": no such variable group");
    if (dot != std::string::npos) {
      const auto& spec = vars.group(refine_group_);
      refine_comp_ = -1;
      for (int c = 0; c < spec.ncomp(); ++c)
        if (spec.components[static_cast<std::size_t>(c)].name == v.substr(dot + 1)) refine_comp_ = c;
      if (refine_comp_ < 0)
        throw InputError({"Grid::refine_variable", 0, 0}, "Grid::refine_variable = " + v + ": group " +
                                                              spec.full_name() + " has no such component");
    }
    if (vars.group(refine_group_).centering != Centering::cell)
      throw InputError({"Grid::refine_variable", 0, 0}, "Grid::refine_variable must be cell-centred");
  }
  auto forest = std::make_unique<Forest>(config_, initial_leaves(config_, *maps_), nranks_);
  std::vector<std::unique_ptr<Block>> blocks;
  const std::int64_t first = forest->first_gid(rank_), count = forest->block_count(rank_);
  for (std::int64_t gid = first; gid < first + count; ++gid) blocks.push_back(make_block(gid, forest->key(gid)));
  install(std::move(forest), std::move(blocks));
}

// The memory estimate comes before any allocation: a grid that cannot fit stops with the parameters named.
AmrGrid::AmrGrid(const GridSetup& setup)
    : AmrGrid(memory_checked(config_from_parameters(setup.params), setup.vars, setup.params, setup.comm), setup.vars,
              setup.comm) {}

AmrGrid::~AmrGrid() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Comm_free(&exchange_comm_);
}

std::unique_ptr<Block> AmrGrid::make_block(std::int64_t gid, const BlockKey& key) const {
  std::array<int, 3> n{}, ng{};
  std::array<double, 3> lo{}, dx{};
  for (std::size_t d = 0; d < 3; ++d) {
    const bool used = static_cast<int>(d) < config_.dimension;
    n[d] = used ? config_.block_size[d] : 1;
    ng[d] = used ? config_.ghost_zones : 0;
    dx[d] = geometry_->spacing(key.level, static_cast<int>(d));
    lo[d] = config_.xmin[d] + static_cast<double>(key.index[d] * n[d]) * dx[d];
  }
  auto b = std::make_unique<Block>(gid, key.level, key.index, n, ng, lo, dx, *vars_);
  b->set_geometry(config_.coordinates, config_.xmin);
  return b;
}

void AmrGrid::install(std::unique_ptr<Forest> forest, std::vector<std::unique_ptr<Block>> blocks) {
  forest_ = std::move(forest);
  blocks_ = std::move(blocks);
  block_ptrs_.clear();
  for (auto& b : blocks_) block_ptrs_.push_back(b.get());
  exchanges_.clear();
  flux_.reset();
  edges_.clear();
  min_spacing_ = compute_min_spacing();
}

int AmrGrid::finest_level() const { return forest_->finest_level(); }

GhostExchange& AmrGrid::exchange_for(const std::array<int, 3>& stagger) {
  auto& e = exchanges_[stagger];
  if (!e)
    e = std::make_unique<GhostExchange>(*forest_, *maps_, *geometry_, block_ptrs_, rank_, exchange_comm_, stagger,
                                        config_.ghost_zones);
  return *e;
}

void AmrGrid::synchronize(std::span<const int> groups) {
  // One exchange per staggering; cell-centred groups first.
  std::map<std::array<int, 3>, std::vector<int>> by_stagger;
  for (int g : groups) {
    const auto& spec = vars_->group(g);
    const auto c = spec.centering;
    if (c == Centering::vertex)
      throw RunError("Grid: synchronising " + std::string(to_string(c)) + "-centred group '" + spec.full_name() +
                     "' is not supported; cell-, face- and edge-centred groups are");
    if (spec.ghosts >= 0 && spec.ghosts < config_.ghost_zones)
      throw RunError("Grid: group '" + spec.full_name() + "' holds " + std::to_string(spec.ghosts) +
                     " ghost layers ('ghosts' at " + spec.where.str() + ") but Grid::ghost_zones is " + std::to_string(config_.ghost_zones) +
                     "; its ghosts cannot be synchronised: read it on the interior, or drop 'ghosts'");
    const auto stagger = effective_stagger(c, config_.dimension);
    for (int d = 0; d < config_.dimension; ++d)
      if (stagger[static_cast<std::size_t>(d)] && config_.max_level > 0 &&
          config_.block_size[static_cast<std::size_t>(d)] < 2 * config_.ghost_zones + 2)
        throw RunError("Grid: synchronising staggered group '" + spec.full_name() + "' on a refined mesh needs "
                       "Grid::block_size >= 2 * Grid::ghost_zones + 2 (its ghost faces reach one face further)");
    by_stagger[stagger].push_back(g);
  }
  for (const auto& [stagger, gs] : by_stagger) {
    exchange_for(stagger).run(*vars_, gs, [&](int phase) {
      // Phase 0 filled every block from same-level and finer neighbours; phase p the blocks of level p.
      for (Block* b : block_ptrs_)
        if (phase == 0 || b->level == phase) apply_outflow(*b, *forest_, config_, *vars_, gs, outflow_conditions_);
    });
  }
}

double AmrGrid::reduce(int group, int comp, ReductionKind kind) {
  const auto& spec = vars_->group(group);
  if (spec.centering != Centering::cell)
    throw RunError("Grid: reductions of " + std::string(to_string(spec.centering)) + "-centred group '" +
                   spec.full_name() + "' are not supported");
  return reduce_blocks(block_ptrs_, *forest_, group, comp, kind, comm_);
}

std::int64_t AmrGrid::global_cells() const {
  const auto& n = forest_->block_cells();
  return forest_->total_blocks() * n[0] * n[1] * n[2];
}

double AmrGrid::compute_min_spacing() const {
  // Proper widths sqrt(f_dd) dx^d at the cell centroids of every leaf (known on every rank).
  double h = std::numeric_limits<double>::infinity();
  const auto& n = forest_->block_cells();
  for (const BlockKey& k : forest_->leaves()) {
    for (int d = 0; d < config_.dimension; ++d) {
      const double dx = geometry_->spacing(k.level, d);
      if (config_.coordinates == CoordinateSystem::cartesian || d == 0 ||
          (config_.coordinates == CoordinateSystem::cylindrical && d == 1)) {
        h = std::min(h, dx);
        continue;
      }
      // theta: r dtheta; phi: R dphi or r sin(theta) dphi. The smallest r (R) and sin(theta) of the block.
      double rmin = std::numeric_limits<double>::infinity(), smin = 1.0;
      for (int i = 0; i < n[0]; ++i) rmin = std::min(rmin, std::abs(geometry_->centroid(k.level, 0, k.index[0] * n[0] + i)));
      if (config_.coordinates == CoordinateSystem::spherical && d == 2 && config_.dimension >= 2)
        for (int j = 0; j < n[1]; ++j)
          smin = std::min(smin, std::abs(std::sin(geometry_->centroid(k.level, 1, k.index[1] * n[1] + j))));
      h = std::min(h, rmin * smin * dx);
    }
  }
  return h;
}

std::vector<BlockKey> AmrGrid::all_blocks() const { return forest_->leaves(); }

void AmrGrid::restore_blocks(std::span<const BlockKey> blocks) {
  for (const BlockKey& k : blocks) {
    const auto nb = forest_->blocks_on_level(k.level);
    bool inside = k.level >= 0 && k.level <= config_.max_level;
    for (std::size_t d = 0; d < 3 && inside; ++d) inside = k.index[d] >= 0 && k.index[d] < nb[d];
    if (!inside)
      throw RunError("the checkpoint's mesh has a block (level " + std::to_string(k.level) +
                     ") that the Grid parameters cannot hold (domain, block size or Grid::max_level differ)");
  }
  auto forest = std::make_unique<Forest>(config_, std::vector<BlockKey>(blocks.begin(), blocks.end()), nranks_);
  if (!std::equal(blocks.begin(), blocks.end(), forest->leaves().begin(), forest->leaves().end()))
    throw RunError("the checkpoint's block list is not in this Grid's curve order (a different Grid version or layout)");
  std::int64_t cells = 0;
  for (const BlockKey& k : forest->leaves()) cells += std::int64_t{1} << (config_.dimension * (forest->finest_level() - k.level));
  const auto base = forest->blocks_on_level(forest->finest_level());
  if (cells != base[0] * base[1] * base[2])
    throw RunError("the checkpoint's blocks do not tile the domain exactly once");
  std::vector<std::unique_ptr<Block>> mine;
  const std::int64_t first = forest->first_gid(rank_), count = forest->block_count(rank_);
  for (std::int64_t gid = first; gid < first + count; ++gid) mine.push_back(make_block(gid, forest->key(gid)));
  install(std::move(forest), std::move(mine));
}

void AmrGrid::correct_fluxes(std::span<const int> face_groups) {
  if (forest_->finest_level() == 0) return;
  if (!flux_) flux_ = std::make_unique<FluxCorrection>(*forest_, *maps_, block_ptrs_, rank_, exchange_comm_);
  flux_->run(*vars_, face_groups);
}

void AmrGrid::correct_edges(std::span<const int> edge_groups) {
  std::map<std::array<int, 3>, std::vector<int>> by_stagger;
  for (int g : edge_groups) {
    const auto c = vars_->group(g).centering;
    if (c != Centering::edge_x && c != Centering::edge_y && c != Centering::edge_z)
      throw RunError("Grid::correct_edges: group '" + vars_->group(g).full_name() + "' is " + to_string(c) +
                     "-centred; EMFs live on edges (edge_x, edge_y or edge_z)");
    by_stagger[effective_stagger(c, config_.dimension)].push_back(g);
  }
  if (forest_->finest_level() == 0) return;
  for (const auto& [stagger, gs] : by_stagger) {
    auto& e = edges_[stagger];
    if (!e) e = std::make_unique<EdgeCorrection>(*forest_, *maps_, block_ptrs_, rank_, exchange_comm_, stagger);
    e->run(*vars_, gs);
  }
}

void AmrGrid::add_outflow_condition(int group, OutflowCondition fn) {
  if (group < 0 || group >= vars_->size()) throw std::logic_error("Grid: outflow condition for an unknown group");
  outflow_conditions_[group].push_back(std::move(fn));
}

void AmrGrid::add_refinement_criterion(const std::string& name, RefinementCriterion fn) {
  criteria_.emplace_back(name, std::move(fn));
}

std::vector<int> AmrGrid::gather_wishes(const std::vector<int>& local) const {
  std::vector<int> counts(static_cast<std::size_t>(nranks_)), displs(static_cast<std::size_t>(nranks_));
  for (int r = 0; r < nranks_; ++r) {
    counts[static_cast<std::size_t>(r)] = static_cast<int>(forest_->block_count(r));
    displs[static_cast<std::size_t>(r)] = static_cast<int>(forest_->first_gid(r));
  }
  std::vector<int> all(static_cast<std::size_t>(forest_->total_blocks()));
  MPI_Allgatherv(local.data(), static_cast<int>(local.size()), MPI_INT, all.data(), counts.data(), displs.data(),
                 MPI_INT, comm_);
  return all;
}

void AmrGrid::synchronize_all() {
  // Prolongation reads the old blocks' ghosts, and the criteria read neighbours: all current.
  // Auxiliary groups (right-hand sides, fluxes) are scratch that their thorn recomputes.
  std::vector<int> all_groups;
  for (int g = 0; g < vars_->size(); ++g) {
    const auto& spec = vars_->group(g);
    const auto c = spec.centering;
    if ((spec.role != VariableRole::auxiliary || g == refine_group_) && c != Centering::vertex)
      all_groups.push_back(g);
  }
  synchronize(all_groups);
}

bool AmrGrid::regrid() {
  synchronize_all();
  std::vector<int> wishes(block_ptrs_.size(), 0);
  const bool adaptive = refine_group_ >= 0 || !criteria_.empty();
  if (adaptive)
    for (std::size_t i = 0; i < block_ptrs_.size(); ++i) {
      Block& b = *block_ptrs_[i];
      int w = -1;  // the block may coarsen unless a criterion objects
      if (refine_group_ >= 0)
        w = std::max(w, lohner_wish(lohner_estimate(b, b.field(refine_group_, refine_comp_), config_.dimension,
                                                    config_.refine_log, config_.lohner_filter),
                                    config_.refine_threshold, config_.derefine_ratio));
      for (auto& [name, fn] : criteria_) w = std::max(w, std::clamp(fn(b), -1, 1));
      wishes[i] = w;
    }
  last_wishes_ = wishes;
  const std::vector<int> all = gather_wishes(wishes);
  return move_to(next_leaves(config_, *forest_, *maps_, all));
}

bool AmrGrid::set_leaves(std::vector<BlockKey> leaves) {
  synchronize_all();
  return move_to(std::move(leaves));
}

bool AmrGrid::move_to(std::vector<BlockKey> leaves) {
  auto next = std::make_unique<Forest>(config_, std::move(leaves), nranks_);
  if (next->leaves() == forest_->leaves()) return false;
  if (const std::string why = balance_violation(config_, *next, *maps_); !why.empty())
    throw RunError("Grid: the new mesh is not 2:1 balanced (internal error): " + why);
  auto make = [this](std::int64_t gid, const BlockKey& key) { return make_block(gid, key); };
  auto blocks = migrate_blocks(*forest_, block_ptrs_, *next, make, make, *vars_, *geometry_, *maps_, face_vectors_, rank_,
                               exchange_comm_, &blocks_);
  install(std::move(next), std::move(blocks));
  return true;
}

Domain AmrGrid::domain() const {
  Domain d;
  d.faces.coordinates = config_.coordinates;
  d.faces.dimension = config_.dimension;
  d.faces.axial_reflection = config_.axial_reflection;
  for (std::size_t e = 0; e < 3; ++e) {
    d.faces.boundary[e] = {config_.boundary_lower[e], config_.boundary_upper[e]};
    const bool used = static_cast<int>(e) < config_.dimension;
    d.cells[e] = used ? config_.ncells[e] : 1;
    d.block_cells[e] = used ? config_.block_size[e] : 1;
    d.lo[e] = config_.xmin[e];
    d.hi[e] = config_.xmax[e];
  }
  return d;
}

}  // namespace remnant::grid
