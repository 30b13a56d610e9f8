#pragma once
// Freed memory kept for reuse by the process's heap (glibc): an xCFC solve allocates and frees
// dozens of level-sized arrays (fields, ghosted copies, transformed components; 160 kB each on the
// 2D migration grid), which glibc by default maps and unmaps, or trims from the heap's top, so
// every solve paid page faults and zeroing again (about a quarter of an xCFC solve's time there).
// The setting (mallopt) holds for the whole process, so the driver makes it at start-up
// (run_main), as do the test programs' main and the XCFC benchmark; once per process; no effect
// with other C libraries. The process keeps its peak heap afterwards.
namespace remnant {

void keep_freed_memory_for_reuse();

}  // namespace remnant
