#include "remnant/comm_counters.hpp"

#include <cstring>

namespace remnant::comm {

namespace {
std::map<Key, Tally>& table() {
  static std::map<Key, Tally> t;
  return t;
}
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

void count(const char* kind, Pattern pattern, int level, long long messages, long long bytes) {
  Tally& t = table()[Key{kind, level}];
  t.pattern = pattern;
  ++t.calls;
  t.messages += messages;
  t.bytes += bytes;
}

void count_work(const char* kind, int level, long long cells) {
  Tally& t = table()[Key{kind, level}];
  t.pattern = Pattern::work;
  ++t.calls;
  t.cells += cells;
}

const std::map<Key, Tally>& tallies() { return table(); }
void reset() { table().clear(); }

}  // namespace remnant::comm
