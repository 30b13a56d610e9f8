#pragma once
// Memory a grid will take per rank, estimated from the settings before anything is allocated, so
// that a grid too large for the machine is refused with the parameters named (issue 16).
#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

#include "Grid/grid_config.hpp"
#include "remnant/variables.hpp"

namespace remnant {
class Parameters;
}

namespace remnant::grid {

// One variable group's storage in one block (Block allocates every group with its ghosts; MoL
// copies the interior of evolved groups at the start of each step).
struct GroupMemory {
  std::string name;             // Thorn::group
  int ncomp = 0;
  double bytes = 0;             // all points, ghosts and staggered points included
  double interior_bytes = 0;    // the interior points (cells, or faces/edges with both block faces)
  double runge_kutta_bytes = 0; // MoL's start-of-step copy: the interior of evolved groups, else 0
};

struct MemoryEstimate {
  std::int64_t blocks_per_rank = 0;  // the most any rank holds
  double bytes_per_block = 0;        // every variable group with ghosts, plus the Runge-Kutta copy of evolved groups
  double bytes_per_rank = 0;         // blocks and the forest's bookkeeping (every rank holds all keys)
};

// Per group, in the registry's order, for one block of `config`'s block size.
std::vector<GroupMemory> group_memory(const GridConfig& config, const VariableRegistry& vars);
// The table of --print-grid's `memory by group`: bytes per block and per interior cell.
std::string format_group_memory(const GridConfig& config, const VariableRegistry& vars);

// `total_blocks` blocks split into contiguous chunks over `nranks`.
MemoryEstimate estimate_memory(const GridConfig& config, const VariableRegistry& vars, std::int64_t total_blocks,
                               int nranks);
// The level-0 block count of a checked config (a lower bound when static regions refine at start).
std::int64_t level0_blocks(const GridConfig& config);

// Bytes of memory of this machine (the cgroup limit where smaller), 0 when unknown.
double machine_memory_bytes();
// The most memory one rank may use: Flesh::max_memory_gb when positive, else the machine's memory
// divided by the ranks sharing the node. Collective over `comm`.
double memory_limit_per_rank(double max_memory_gb, MPI_Comm comm);

// Throws InputError naming Grid::ncells, Grid::block_size (and Flesh::max_memory_gb) when the
// level-0 grid would not fit. Collective. Returns the config unchanged.
GridConfig memory_checked(const GridConfig& config, const VariableRegistry& vars, const Parameters& params,
                          MPI_Comm comm);

std::string format_bytes(double bytes);

}  // namespace remnant::grid
