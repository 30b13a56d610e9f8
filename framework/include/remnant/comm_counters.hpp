#pragma once
// Tallies of this rank's MPI traffic by kind (ghost exchange, multigrid transfers per level,
// reductions) and of counted work, for the scaling model (utils/scaling_model). A call adds one
// entry to a small map keyed by a string literal and a level: a few tens of nanoseconds next to
// an MPI call, and no data is touched, so the bits of a run do not change.
// Bytes are payload bytes: for point-to-point messages those this rank sends, for allgathers those
// it receives (the others' parts), for allreduces the reduced array's size. Messages: point-to-
// point messages sent; one per collective call.
// The driver clears the tallies when the evolution starts (initial data are not counted) and, with
// Flesh::comm_stats, writes every rank's tallies and timers to <out_dir>/comm.tsv at the end.
#include <map>
#include <string>

namespace remnant::comm {

enum class Pattern { p2p, allreduce, allgather, alltoall, gather, work };
const char* pattern_name(Pattern p);

struct Tally {
  Pattern pattern = Pattern::p2p;
  long long calls = 0, messages = 0, bytes = 0, cells = 0;
};

struct Key {
  const char* kind;  // a string literal: it outlives the tally
  int level;
  bool operator<(const Key& o) const;
};

// `kind` must be a string literal (or live as long as the program). `cells`: points per component
// moved (ghost exchange), for the model's surface-to-volume law.
void count(const char* kind, Pattern pattern, int level, long long messages, long long bytes, long long cells = 0);
// Work that the model costs per cell (e.g. cells relaxed on a multigrid level).
void count_work(const char* kind, int level, long long cells);

const std::map<Key, Tally>& tallies();
// Clears the tallies and starts the clocks of the counted interval (process CPU time and wall
// time: on a shared machine the CPU time is the better measure of this rank's work).
void reset();
double cpu_seconds();   // this process's CPU time since reset()
double wall_seconds();  // wall time since reset()
// CPU time inside MPI since reset() when utils/scaling_model's mpi_cpu_preload library is
// preloaded (LD_PRELOAD), else 0: CPU time less this is this rank's work on a shared machine.
double mpi_cpu_seconds();
double work_seconds();  // cpu_seconds() - mpi_cpu_seconds()

}  // namespace remnant::comm
