// The layout for --print-grid: coordinates, domain, levels (blocks, cells, spacing), ranks.
#include <algorithm>
#include <sstream>

#include "Grid/amr_grid.hpp"
#include "config.hpp"
#include "forest.hpp"
#include "memory_estimate.hpp"

namespace remnant::grid {

std::string AmrGrid::describe() const {
  const int dim = config_.dimension;
  const Forest& f = *forest_;
  auto joined = [dim](auto value) {
    std::ostringstream s;
    for (int d = 0; d < dim; ++d) s << (d ? " x " : "") << value(static_cast<std::size_t>(d));
    return s.str();
  };
  std::int64_t min_blocks = f.total_blocks(), max_blocks = 0;
  for (int r = 0; r < nranks_; ++r) {
    min_blocks = std::min(min_blocks, f.block_count(r));
    max_blocks = std::max(max_blocks, f.block_count(r));
  }
  const auto per_level = f.blocks_per_level();
  const auto& n = f.block_cells();
  const std::int64_t cells_per_block = static_cast<std::int64_t>(n[0]) * n[1] * n[2];
  std::ostringstream out;
  out << "Grid: " << (config_.max_level > 0 ? "adaptive" : "uniform") << ", " << to_string(config_.coordinates)
      << " coordinates, " << dim << "D, " << per_level.size() << " level" << (per_level.size() > 1 ? "s" : "")
      << " (Grid::max_level = " << config_.max_level << ")\n"
      << "  domain      " << joined([&](std::size_t d) {
           std::ostringstream s;
           s << "[" << config_.xmin[d] << ", " << config_.xmax[d] << "]";
           return s.str();
         }) << "\n"
      << "  cells       " << joined([&](std::size_t d) { return config_.ncells[d]; }) << " on level 0; "
      << global_cells() << " in all\n"
      << "  blocks      " << joined([&](std::size_t d) { return config_.block_size[d]; }) << " cells each, "
      << f.total_blocks() << " blocks along a Morton curve\n";
  for (std::size_t l = 0; l < per_level.size(); ++l) {
    out << "  level " << l << "     " << per_level[l] << " blocks, " << per_level[l] * cells_per_block
        << " cells, spacing " << joined([&](std::size_t d) {
             std::ostringstream s;
             s << (config_.xmax[d] - config_.xmin[d]) / static_cast<double>(config_.ncells[d]) /
                      static_cast<double>(std::int64_t{1} << l);
             return s.str();
           })
        << "\n";
  }
  const MemoryEstimate memory = estimate_memory(config_, *vars_, f.total_blocks(), nranks_);
  out << "  ranks       " << nranks_ << ", blocks per rank " << min_blocks
      << (min_blocks == max_blocks ? "" : " to " + std::to_string(max_blocks)) << "\n"
      << "  memory      about " << format_bytes(memory.bytes_per_rank) << " per rank (" << format_bytes(memory.bytes_per_block)
      << " per block: variables with ghosts, Runge-Kutta copies); this machine has "
      << format_bytes(machine_memory_bytes()) << "\n"
      << format_group_memory(config_, *vars_) << "  ghosts      " << config_.ghost_zones << "\n"
      << "  min spacing " << min_spacing_ << " (proper length)\n"
      << "  boundaries  ";
  static const char* const names[3][3] = {{"x", "y", "z"}, {"R", "z", "phi"}, {"r", "theta", "phi"}};
  const auto cs = static_cast<std::size_t>(config_.coordinates);
  for (int d = 0; d < dim; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    out << (d ? ", " : "") << names[cs][ud] << ": " << to_string(config_.boundary_lower[ud]);
    if (config_.boundary_upper[ud] != config_.boundary_lower[ud]) out << "/" << to_string(config_.boundary_upper[ud]);
  }
  out << "\n";
  for (std::size_t r = 0; r < config_.regions.size(); ++r) {
    const auto& reg = config_.regions[r];
    out << "  region " << r << "    " << (reg.kind == RegionKind::box ? "box" : reg.kind == RegionKind::sphere ? "sphere" : "shell")
        << (reg.mode == RegionMode::at_least ? " at least" : " at most") << " level " << reg.level << ", bounds";
    for (double b : reg.bounds) out << " " << b;
    out << "\n";
  }
  if (!config_.refine_variable.empty())
    out << "  adaptive    Löhner on " << config_.refine_variable << (config_.refine_log ? " (log)" : "")
        << ", threshold " << config_.refine_threshold << ", derefine ratio " << config_.derefine_ratio << "\n";
  if (!criteria_.empty()) {
    out << "  criteria   ";
    for (const auto& [name, fn] : criteria_) out << " " << name;
    out << "\n";
  }
  return out.str();
}

}  // namespace remnant::grid
