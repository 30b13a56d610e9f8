#include "Grid/uniform_grid.hpp"

#include <algorithm>
#include <sstream>

#include "block_layout.hpp"
#include "config.hpp"
#include "ghost_exchange.hpp"
#include "outer_boundary.hpp"
#include "reduction.hpp"
#include "remnant/error.hpp"

namespace remnant::grid {

namespace {
// The cell count and spacing per direction; an unused direction is one cell spanning its extent.
std::array<double, 3> cell_widths(const UniformGridConfig& c) {
  std::array<double, 3> dx{};
  for (std::size_t d = 0; d < 3; ++d) dx[d] = (c.xmax[d] - c.xmin[d]) / static_cast<double>(c.ncells[d]);
  return dx;
}
}  // namespace

UniformGrid::UniformGrid(const UniformGridConfig& config, const VariableRegistry& vars, MPI_Comm comm)
    : config_(checked(config)), vars_(&vars), comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &nranks_);
  MPI_Comm_dup(comm, &exchange_comm_);
  layout_ = std::make_unique<BlockLayout>(config_, nranks_);

  const auto dx = cell_widths(config_);
  std::array<int, 3> n{}, ng{};
  for (std::size_t d = 0; d < 3; ++d) {
    const bool used = static_cast<int>(d) < config_.dimension;
    n[d] = used ? config_.block_size[d] : 1;
    ng[d] = used ? config_.ghost_zones : 0;
  }
  const std::int64_t first = layout_->first_gid(rank_), count = layout_->block_count(rank_);
  for (std::int64_t gid = first; gid < first + count; ++gid) {
    const auto& index = layout_->index_of(gid);
    std::array<double, 3> lo{};
    for (std::size_t d = 0; d < 3; ++d)
      lo[d] = config_.xmin[d] + static_cast<double>(index[d] * n[d]) * dx[d];
    blocks_.push_back(std::make_unique<Block>(gid, 0, index, n, ng, lo, dx, vars));
    block_ptrs_.push_back(blocks_.back().get());
  }
  exchange_ = std::make_unique<GhostExchange>(*layout_, block_ptrs_, rank_, exchange_comm_);
}

UniformGrid::UniformGrid(const GridSetup& setup)
    : UniformGrid(config_from_parameters(setup.params), setup.vars, setup.comm) {}

UniformGrid::~UniformGrid() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Comm_free(&exchange_comm_);
}

void UniformGrid::synchronize(std::span<const int> groups) {
  for (int g : groups) {
    const auto& spec = vars_->group(g);
    if (spec.centering != Centering::cell)
      throw RunError("Grid: synchronising " + std::string(to_string(spec.centering)) +
                     "-centred group '" + spec.full_name() +
                     "' is not yet supported; only cell-centred groups have ghost exchange so far");
  }
  exchange_->run(*vars_, groups);
  for (Block* b : block_ptrs_) apply_outer_boundaries(*b, *layout_, config_, *vars_, groups);
}

double UniformGrid::reduce(int group, int comp, ReductionKind kind) {
  const auto& spec = vars_->group(group);
  if (spec.centering != Centering::cell)
    throw RunError("Grid: reductions of " + std::string(to_string(spec.centering)) +
                   "-centred group '" + spec.full_name() + "' are not yet supported");
  return reduce_blocks(block_ptrs_, *layout_, group, comp, kind, comm_);
}

std::int64_t UniformGrid::global_cells() const {
  return config_.ncells[0] * config_.ncells[1] * config_.ncells[2];
}

double UniformGrid::min_spacing() const {
  const auto dx = cell_widths(config_);
  return *std::min_element(dx.begin(), dx.begin() + config_.dimension);
}

std::string UniformGrid::describe() const {
  const int dim = config_.dimension;
  const auto dx = cell_widths(config_);
  const auto& nb = layout_->blocks_per_direction();
  auto joined = [dim](auto value) {
    std::ostringstream s;
    for (int d = 0; d < dim; ++d) s << (d ? " x " : "") << value(static_cast<std::size_t>(d));
    return s.str();
  };
  std::int64_t min_blocks = layout_->total_blocks(), max_blocks = 0;
  for (int r = 0; r < nranks_; ++r) {
    min_blocks = std::min(min_blocks, layout_->block_count(r));
    max_blocks = std::max(max_blocks, layout_->block_count(r));
  }
  std::ostringstream out;
  out << "Grid: uniform, " << config_.coordinates << " coordinates, " << dim << "D, 1 level\n"
      << "  domain      " << joined([&](std::size_t d) {
           std::ostringstream s;
           s << "[" << config_.xmin[d] << ", " << config_.xmax[d] << "]";
           return s.str();
         }) << "\n"
      << "  cells       " << joined([&](std::size_t d) { return config_.ncells[d]; }) << " = "
      << global_cells() << ", spacing " << joined([&](std::size_t d) { return dx[d]; }) << "\n"
      << "  blocks      " << joined([&](std::size_t d) { return config_.block_size[d]; })
      << " cells each, " << joined([&](std::size_t d) { return nb[d]; }) << " = "
      << layout_->total_blocks() << " blocks along a Morton curve\n"
      << "  ranks       " << nranks_ << ", blocks per rank " << min_blocks
      << (min_blocks == max_blocks ? "" : " to " + std::to_string(max_blocks)) << "\n"
      << "  ghosts      " << config_.ghost_zones << "\n"
      << "  boundaries  ";
  const char* axis[3] = {"x", "y", "z"};
  for (int d = 0; d < dim; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    out << (d ? ", " : "") << axis[d] << ": " << to_string(config_.boundary_lower[ud]);
    if (config_.boundary_upper[ud] != config_.boundary_lower[ud])
      out << "/" << to_string(config_.boundary_upper[ud]);
  }
  out << "\n";
  return out.str();
}

std::vector<BlockKey> UniformGrid::all_blocks() const {
  std::vector<BlockKey> out;
  for (std::int64_t gid = 0; gid < layout_->total_blocks(); ++gid) {
    const auto& idx = layout_->index_of(gid);
    out.push_back(BlockKey{0, {idx[0], idx[1], idx[2]}});
  }
  return out;
}

void UniformGrid::restore_blocks(std::span<const BlockKey> blocks) {
  // A uniform grid has one possible layout: the checkpoint must describe the same one.
  const auto mine = all_blocks();
  if (blocks.size() != mine.size() || !std::equal(blocks.begin(), blocks.end(), mine.begin()))
    throw RunError("the checkpoint's mesh (" + std::to_string(blocks.size()) + " blocks) differs from the mesh of "
                   "the Grid parameters (" + std::to_string(mine.size()) + " blocks): recover with the same Grid settings");
  for (Block* b : block_ptrs_)
    for (int g = 0; g < vars_->size(); ++g) std::fill(b->data(g), b->data(g) + b->size(g), 0.0);
}

}  // namespace remnant::grid
