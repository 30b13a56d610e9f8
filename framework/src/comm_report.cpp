#include "comm_report.hpp"

#include <mpi.h>

#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "remnant/comm_counters.hpp"
#include "remnant/error.hpp"
#include "remnant/grid.hpp"

namespace remnant {

namespace {

// This rank's rows: rank kind level pattern calls messages bytes cells seconds.
std::string rows_of_rank(const Scheduler& s, Context& ctx) {
  std::ostringstream os;
  os.precision(9);
  const int r = ctx.rank();
  for (const auto& [key, t] : comm::tallies())
    os << r << '\t' << key.kind << '\t' << key.level << '\t' << comm::pattern_name(t.pattern) << '\t' << t.calls << '\t'
       << t.messages << '\t' << t.bytes << '\t' << t.cells << "\t0\n";
  for (const ScheduleNode* n : s.all_functions())
    if (n->calls > 0)
      os << r << "\ttimer:" << n->item->thorn << "::" << n->item->name << "\t-1\ttimer\t" << n->calls << "\t0\t0\t0\t"
         << n->seconds << '\n' << r << "\twork:" << n->item->thorn << "::" << n->item->name << "\t-1\ttimer\t" << n->calls
         << "\t0\t0\t0\t" << n->work_seconds << '\n';
  os << r << "\ttimer:ghost_sync\t-1\ttimer\t" << s.sync_calls() << "\t0\t0\t0\t" << s.sync_seconds() << '\n';
  if (ctx.has_grid()) {
    // Blocks and interior cells per level owned by this rank: the model's decomposition.
    std::map<int, std::pair<long long, long long>> per_level;
    for (Block* b : ctx.grid().local_blocks()) {
      auto& [blocks, cells] = per_level[b->level];
      ++blocks;
      cells += static_cast<long long>(b->n[0]) * b->n[1] * b->n[2];
    }
    const auto cells0 = ctx.grid().domain().cells;  // level 0 of the domain: the multigrid's base
    os << r << "\tgrid:domain\t0\tgrid\t1\t0\t0\t" << cells0[0] * cells0[1] * cells0[2] << "\t0\n";
    for (const auto& [level, bc] : per_level)
      os << r << "\tgrid:blocks\t" << level << "\tgrid\t" << bc.first << "\t0\t0\t" << bc.second << "\t0\n";
  }
  os << r << "\tgrid:iterations\t-1\tgrid\t" << ctx.iteration() << "\t0\t0\t0\t0\n";
  // Since the tallies were cleared (the evolution): this process's CPU time and the wall time.
  os << r << "\tclock:cpu\t-1\ttimer\t1\t0\t0\t0\t" << comm::cpu_seconds() << '\n';
  os << r << "\tclock:wall\t-1\ttimer\t1\t0\t0\t0\t" << comm::wall_seconds() << '\n';
  os << r << "\tclock:mpi_cpu\t-1\ttimer\t1\t0\t0\t0\t" << comm::mpi_cpu_seconds() << '\n';
  return os.str();
}

}  // namespace

void write_comm_report(const Scheduler& s, Context& ctx) {
  const std::string mine = rows_of_rank(s, ctx);
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(ctx.nranks())), displs(counts.size(), 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, ctx.comm());
  std::partial_sum(counts.begin(), counts.end() - 1, displs.begin() + 1);
  std::string all(ctx.rank() == 0 ? static_cast<std::size_t>(displs.back() + counts.back()) : 0, '\0');
  MPI_Gatherv(mine.data(), n, MPI_CHAR, all.data(), counts.data(), displs.data(), MPI_CHAR, 0, ctx.comm());
  if (ctx.rank() != 0) return;
  const std::string path = ctx.out_dir() + "/comm.tsv";
  std::ofstream out(path);
  out << "# Remnant communication tallies (Flesh::comm_stats), " << ctx.nranks() << " ranks\n"
      << "# bytes: p2p sent, allgather received, allreduce array size; messages: p2p sent, 1 per collective\n"
      << "rank\tkind\tlevel\tpattern\tcalls\tmessages\tbytes\tcells\tseconds\n"
      << all;
  if (!out) throw RunError("cannot write " + path + " (Flesh::out_dir)");
}

}  // namespace remnant
