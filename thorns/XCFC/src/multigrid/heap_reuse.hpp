#pragma once
// Freed memory kept for reuse by the process's heap (glibc): a solve allocates and frees dozens of
// level-sized arrays (fields, ghosted copies, transformed components; 160 kB each on the 2D
// migration grid), which glibc by default maps and unmaps, or trims from the heap's top, so every
// solve paid page faults and zeroing again (about a quarter of an xCFC solve's time there).
// Called when a Multigrid is built; once per process; no effect with other C libraries.
namespace remnant::xcfc {

void keep_freed_memory_for_reuse();

}  // namespace remnant::xcfc
