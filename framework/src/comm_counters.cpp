#include "remnant/comm_counters.hpp"

#include <dlfcn.h>

#include <chrono>
#include <cstring>
#include <ctime>

namespace remnant::comm {

namespace {
std::map<Key, Tally>& table() {
  static std::map<Key, Tally> t;
  return t;
}
double process_cpu() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
double wall_now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
// CPU time inside MPI where utils/scaling_model's mpi_cpu_preload library is preloaded, else 0.
double mpi_cpu() {
  using Reader = double (*)();
  static const auto reader = reinterpret_cast<Reader>(dlsym(RTLD_DEFAULT, "remnant_mpi_cpu_seconds"));
  return reader ? reader() : 0.0;
}
double cpu_start = process_cpu(), wall_start = wall_now(), mpi_cpu_start = 0;
}  // namespace

const char* pattern_name(Pattern p) {
  switch (p) {
    case Pattern::p2p: return "p2p";
    case Pattern::allreduce: return "allreduce";
    case Pattern::allgather: return "allgather";
    case Pattern::alltoall: return "alltoall";
    case Pattern::gather: return "gather";
    case Pattern::work: return "work";
  }
  return "?";
}

bool Key::operator<(const Key& o) const {
  const int c = std::strcmp(kind, o.kind);
  return c != 0 ? c < 0 : level < o.level;
}

void count(const char* kind, Pattern pattern, int level, long long messages, long long bytes, long long cells) {
  Tally& t = table()[Key{kind, level}];
  t.pattern = pattern;
  ++t.calls;
  t.messages += messages;
  t.bytes += bytes;
  t.cells += cells;
}

void count_work(const char* kind, int level, long long cells) {
  Tally& t = table()[Key{kind, level}];
  t.pattern = Pattern::work;
  ++t.calls;
  t.cells += cells;
}

const std::map<Key, Tally>& tallies() { return table(); }
void reset() {
  table().clear();
  cpu_start = process_cpu();
  wall_start = wall_now();
  mpi_cpu_start = mpi_cpu();
}
double cpu_seconds() { return process_cpu() - cpu_start; }
double wall_seconds() { return wall_now() - wall_start; }
double mpi_cpu_seconds() { return mpi_cpu() - mpi_cpu_start; }
double work_seconds() { return cpu_seconds() - mpi_cpu_seconds(); }

}  // namespace remnant::comm
