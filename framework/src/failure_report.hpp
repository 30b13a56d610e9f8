#pragma once
// Stopping every rank after a failure with one clear message: the lowest failing rank prints it,
// once, without MPI runtime noise when every rank failed together (or there is only one rank).
#include <mpi.h>

#include <exception>
#include <string>

namespace remnant {

// The line to print for an exception thrown while `thorn::function` ran (empty thorn: none did).
// Input errors keep their "file:line:col: error: ..." form; other failures read
// "ERROR [rank r] in Thorn::function: ..." (the rank only when there are several).
std::string failure_message(const std::exception& e, const std::string& thorn, const std::string& function, int rank,
                            int nranks);

struct FailureOutcome {
  bool all_failed = false;  // every rank failed: each may finalise MPI and exit (no MPI_Abort)
  bool printed = false;     // this rank printed the message (it is the lowest failing rank)
};

// Tells the other ranks (on `error_comm`, a communicator only this function uses) that this rank
// failed, waits up to `wait_seconds` to hear which others failed too, and prints `message` on stderr
// when this is the lowest failing rank. When some rank is still running the caller must MPI_Abort.
FailureOutcome report_failure(const std::string& message, MPI_Comm error_comm, double wait_seconds = 2.0);

}  // namespace remnant
