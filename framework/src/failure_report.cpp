#include "failure_report.hpp"

#include <cstdio>
#include <new>
#include <set>
#include <vector>

#include "remnant/error.hpp"

namespace remnant {

namespace {
constexpr int kFailureTag = 7316;
}

std::string failure_message(const std::exception& e, const std::string& thorn, const std::string& function, int rank,
                            int nranks) {
  std::string what = e.what();
  if (dynamic_cast<const std::bad_alloc*>(&e))
    what = "out of memory (" + what + "): the run needs more memory than this machine gives each rank; see the "
           "estimate of --print-grid, use fewer cells or more nodes";
  if (dynamic_cast<const InputError*>(&e)) return what;
  std::string out = "ERROR";
  if (nranks > 1) out += " [rank " + std::to_string(rank) + "]";
  if (!thorn.empty()) out += " in " + thorn + "::" + function;
  return out + ": " + what;
}

FailureOutcome report_failure(const std::string& message, MPI_Comm error_comm, double wait_seconds) {
  int rank = 0, size = 1;
  MPI_Comm_rank(error_comm, &rank);
  MPI_Comm_size(error_comm, &size);
  auto print = [&] { std::fprintf(stderr, "%s\n", message.c_str()); std::fflush(stderr); };
  if (size == 1) {
    print();
    return {true, true};
  }
  // Announce the failure to every other rank; ranks that failed too are polling for these.
  std::vector<MPI_Request> sends;
  for (int r = 0; r < size; ++r)
    if (r != rank) {
      sends.emplace_back();
      MPI_Issend(&rank, 1, MPI_INT, r, kFailureTag, error_comm, &sends.back());
    }
  std::set<int> failed{rank};
  const double t0 = MPI_Wtime();
  while (static_cast<int>(failed.size()) < size && MPI_Wtime() - t0 < wait_seconds) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kFailureTag, error_comm, &flag, &st);
    if (!flag) continue;
    int who = 0;
    MPI_Recv(&who, 1, MPI_INT, st.MPI_SOURCE, kFailureTag, error_comm, MPI_STATUS_IGNORE);
    failed.insert(who);
  }
  const bool all_failed = static_cast<int>(failed.size()) == size;
  const bool lowest = *failed.begin() == rank;
  if (lowest) print();
  if (all_failed) MPI_Waitall(static_cast<int>(sends.size()), sends.data(), MPI_STATUSES_IGNORE);
  return {all_failed, lowest};
}

}  // namespace remnant
