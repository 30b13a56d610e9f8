// LD_PRELOAD library for the scaling model's check on a shared machine: the CPU time this process
// spends inside MPI (PMPI wrappers of the calls Remnant makes). A rank that waits for another busy-
// polls, so on an oversubscribed machine its CPU time is not its work; its CPU time outside MPI
// is. remnant_mpi_cpu_seconds() is found by the flesh with dlsym (remnant/comm_counters.hpp) and
// written to comm.tsv as clock:mpi_cpu. Not linked into anything: check_two_ranks.sh preloads it.
#include <mpi.h>
#include <time.h>

namespace {
double in_mpi = 0;
double thread_cpu() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
struct Timed {
  double t0 = thread_cpu();
  ~Timed() { in_mpi += thread_cpu() - t0; }
};
}  // namespace

extern "C" {
double remnant_mpi_cpu_seconds() { return in_mpi; }

int MPI_Waitall(int n, MPI_Request r[], MPI_Status s[]) { Timed t; return PMPI_Waitall(n, r, s); }
int MPI_Wait(MPI_Request* r, MPI_Status* s) { Timed t; return PMPI_Wait(r, s); }
int MPI_Barrier(MPI_Comm c) { Timed t; return PMPI_Barrier(c); }
int MPI_Recv(void* b, int n, MPI_Datatype d, int src, int tag, MPI_Comm c, MPI_Status* s) {
  Timed t;
  return PMPI_Recv(b, n, d, src, tag, c, s);
}
int MPI_Send(const void* b, int n, MPI_Datatype d, int dst, int tag, MPI_Comm c) {
  Timed t;
  return PMPI_Send(b, n, d, dst, tag, c);
}
int MPI_Sendrecv(const void* sb, int sn, MPI_Datatype sd, int dst, int stag, void* rb, int rn, MPI_Datatype rd, int src,
                 int rtag, MPI_Comm c, MPI_Status* s) {
  Timed t;
  return PMPI_Sendrecv(sb, sn, sd, dst, stag, rb, rn, rd, src, rtag, c, s);
}
int MPI_Allreduce(const void* sb, void* rb, int n, MPI_Datatype d, MPI_Op op, MPI_Comm c) {
  Timed t;
  return PMPI_Allreduce(sb, rb, n, d, op, c);
}
int MPI_Bcast(void* b, int n, MPI_Datatype d, int root, MPI_Comm c) { Timed t; return PMPI_Bcast(b, n, d, root, c); }
int MPI_Allgather(const void* sb, int sn, MPI_Datatype sd, void* rb, int rn, MPI_Datatype rd, MPI_Comm c) {
  Timed t;
  return PMPI_Allgather(sb, sn, sd, rb, rn, rd, c);
}
int MPI_Allgatherv(const void* sb, int sn, MPI_Datatype sd, void* rb, const int rn[], const int dis[], MPI_Datatype rd,
                   MPI_Comm c) {
  Timed t;
  return PMPI_Allgatherv(sb, sn, sd, rb, rn, dis, rd, c);
}
int MPI_Alltoallv(const void* sb, const int sn[], const int sdis[], MPI_Datatype sd, void* rb, const int rn[],
                  const int rdis[], MPI_Datatype rd, MPI_Comm c) {
  Timed t;
  return PMPI_Alltoallv(sb, sn, sdis, sd, rb, rn, rdis, rd, c);
}
int MPI_Gather(const void* sb, int sn, MPI_Datatype sd, void* rb, int rn, MPI_Datatype rd, int root, MPI_Comm c) {
  Timed t;
  return PMPI_Gather(sb, sn, sd, rb, rn, rd, root, c);
}
int MPI_Gatherv(const void* sb, int sn, MPI_Datatype sd, void* rb, const int rn[], const int dis[], MPI_Datatype rd,
                int root, MPI_Comm c) {
  Timed t;
  return PMPI_Gatherv(sb, sn, sd, rb, rn, dis, rd, root, c);
}
int MPI_Scatterv(const void* sb, const int sn[], const int dis[], MPI_Datatype sd, void* rb, int rn, MPI_Datatype rd,
                 int root, MPI_Comm c) {
  Timed t;
  return PMPI_Scatterv(sb, sn, dis, sd, rb, rn, rd, root, c);
}
}
