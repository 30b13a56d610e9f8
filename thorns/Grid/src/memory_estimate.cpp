#include "memory_estimate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "remnant/error.hpp"
#include "remnant/parameters.hpp"

namespace remnant::grid {

namespace {
// Keys, owners and neighbour lists of one block in the forest, held on every rank (rough).
constexpr double kForestBytesPerBlock = 200;
}  // namespace

std::int64_t level0_blocks(const GridConfig& c) {
  std::int64_t blocks = 1;
  for (int d = 0; d < c.dimension; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    blocks *= std::max<std::int64_t>(1, c.ncells[ud] / std::max(1, c.block_size[ud]));
  }
  return blocks;
}

std::vector<GroupMemory> group_memory(const GridConfig& c, const VariableRegistry& vars) {
  std::vector<GroupMemory> out;
  const auto evolved = vars.evolved();
  for (const auto& g : vars.groups()) {
    const auto st = staggering(g.centering);
    double points = 1, interior = 1;
    const int ghosts = g.ghosts >= 0 ? std::min(g.ghosts, c.ghost_zones) : c.ghost_zones;
    for (int d = 0; d < c.dimension; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      points *= c.block_size[ud] + 2 * ghosts + st[ud];
      interior *= c.block_size[ud] + st[ud];
    }
    const bool is_evolved = std::find(evolved.begin(), evolved.end(), g.id) != evolved.end();
    const double per_point = g.ncomp() * static_cast<double>(sizeof(double));
    out.push_back({g.full_name(), g.ncomp(), points * per_point, interior * per_point,
                   is_evolved ? interior * per_point : 0.0});
  }
  return out;
}

std::string format_group_memory(const GridConfig& c, const VariableRegistry& vars) {
  double cells = 1;
  for (int d = 0; d < c.dimension; ++d) cells *= c.block_size[static_cast<std::size_t>(d)];
  std::ostringstream out;
  char line[160];
  double total = 0;
  out << "  memory by group (per block with ghosts; bytes per interior cell; +RK: MoL's copy)\n";
  for (const GroupMemory& g : group_memory(c, vars)) {
    const double bytes = g.bytes + g.runge_kutta_bytes;
    total += bytes;
    std::snprintf(line, sizeof line, "    %-36s %2d comp %10s %8.0f B/cell%s\n", g.name.c_str(), g.ncomp,
                  format_bytes(bytes).c_str(), bytes / cells, g.runge_kutta_bytes > 0 ? " (+RK)" : "");
    out << line;
  }
  std::snprintf(line, sizeof line, "    %-36s         %10s %8.0f B/cell\n", "all groups", format_bytes(total).c_str(),
                total / cells);
  out << line;
  return out.str();
}

MemoryEstimate estimate_memory(const GridConfig& c, const VariableRegistry& vars, std::int64_t total_blocks,
                               int nranks) {
  MemoryEstimate m;
  for (const GroupMemory& g : group_memory(c, vars)) m.bytes_per_block += g.bytes + g.runge_kutta_bytes;
  m.blocks_per_rank = (total_blocks + nranks - 1) / std::max(1, nranks);
  m.bytes_per_rank = m.bytes_per_block * static_cast<double>(m.blocks_per_rank) +
                     kForestBytesPerBlock * static_cast<double>(total_blocks);
  return m;
}

double machine_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  double bytes = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
  // A container's limit (cgroup v2, then v1) is what the run really gets.
  for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(path);
    double limit = 0;
    if (in >> limit && limit > 0 && (bytes == 0 || limit < bytes)) bytes = limit;
  }
  return bytes;
}

double memory_limit_per_rank(double max_memory_gb, MPI_Comm comm) {
  if (max_memory_gb > 0) return max_memory_gb * 1e9;
  MPI_Comm node;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int on_node = 1;
  MPI_Comm_size(node, &on_node);
  MPI_Comm_free(&node);
  return machine_memory_bytes() / on_node;
}

std::string format_bytes(double bytes) {
  char buf[64];
  if (bytes >= 1e12) std::snprintf(buf, sizeof buf, "%.3g TB", bytes / 1e12);
  else if (bytes >= 1e9) std::snprintf(buf, sizeof buf, "%.3g GB", bytes / 1e9);
  else if (bytes >= 1e6) std::snprintf(buf, sizeof buf, "%.3g MB", bytes / 1e6);
  else std::snprintf(buf, sizeof buf, "%.3g kB", bytes / 1e3);
  return buf;
}

GridConfig memory_checked(const GridConfig& config, const VariableRegistry& vars, const Parameters& params,
                          MPI_Comm comm) {
  int nranks = 1;
  MPI_Comm_size(comm, &nranks);
  // Tools and tests may build a grid from Grid parameters alone.
  const double max_gb = params.find("Flesh", "max_memory_gb") ? params.get<double>("Flesh", "max_memory_gb") : 0.0;
  const double limit = memory_limit_per_rank(max_gb, comm);
  const std::int64_t blocks = level0_blocks(config);
  const MemoryEstimate m = estimate_memory(config, vars, blocks, nranks);
  if (limit > 0 && m.bytes_per_rank > limit) {
    std::ostringstream msg;
    msg << "the grid needs about " << format_bytes(m.bytes_per_rank) << " per rank on level 0 alone (" << blocks
        << " blocks of Grid::block_size cells over " << nranks << " rank" << (nranks > 1 ? "s" : "") << ", "
        << format_bytes(m.bytes_per_block) << " per block for " << vars.size()
        << " variable groups with ghosts and Runge-Kutta copies), but a rank may use "
        << format_bytes(limit)
        << (max_gb > 0 ? " (Flesh::max_memory_gb)" : " (this machine's memory over its ranks; set Flesh::max_memory_gb to change)")
        << ": lower Grid::ncells, use more ranks or nodes";
    throw InputError(params.origin("Grid", "ncells"), msg.str());
  }
  return config;
}

}  // namespace remnant::grid
