// Ping-pong between ranks 0 and 1 (mpirun -np 2): one-way time per message size, the minimum over
// repetitions (the machine is shared, so the minimum is the cost the network model needs). Prints
// "bytes<TAB>seconds" rows, then the fit t = alpha + bytes / bandwidth that
// utils/scaling_model reads (`--pingpong FILE`), and the time of an 8-byte MPI_Allreduce.
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size != 2) {
    if (rank == 0) std::fprintf(stderr, "mpi_pingpong: run on exactly 2 ranks (mpirun -np 2), got %d\n", size);
    MPI_Finalize();
    return 1;
  }
  const int peer = 1 - rank;
  std::vector<double> buf(1 << 20);
  std::vector<double> sizes, times;
  if (rank == 0) std::printf("# bytes\tone_way_seconds (min over repetitions)\n");
  for (std::size_t n = 1; n <= buf.size(); n *= 4) {
    const int reps = n < 4096 ? 200 : 20;
    double best = 1e30;
    for (int r = 0; r < reps; ++r) {
      MPI_Barrier(MPI_COMM_WORLD);
      const double t0 = MPI_Wtime();
      if (rank == 0) {
        MPI_Send(buf.data(), static_cast<int>(n), MPI_DOUBLE, peer, 0, MPI_COMM_WORLD);
        MPI_Recv(buf.data(), static_cast<int>(n), MPI_DOUBLE, peer, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      } else {
        MPI_Recv(buf.data(), static_cast<int>(n), MPI_DOUBLE, peer, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        MPI_Send(buf.data(), static_cast<int>(n), MPI_DOUBLE, peer, 0, MPI_COMM_WORLD);
      }
      best = std::min(best, (MPI_Wtime() - t0) / 2);
    }
    if (rank == 0) std::printf("%zu\t%.6e\n", 8 * n, best);
    sizes.push_back(8.0 * static_cast<double>(n));
    times.push_back(best);
  }
  double allreduce = 1e30;
  for (int r = 0; r < 200; ++r) {
    double x = rank, y = 0;
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    MPI_Allreduce(&x, &y, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    allreduce = std::min(allreduce, MPI_Wtime() - t0);
  }
  if (rank == 0) {
    // Latency: the smallest message; inverse bandwidth: the slope between the two largest.
    const std::size_t k = sizes.size() - 1;
    const double alpha = times.front();
    const double beta = (times[k] - times[k - 1]) / (sizes[k] - sizes[k - 1]);
    std::printf("alpha_s\t%.6e\nbandwidth_Bps\t%.6e\nallreduce_8B_s\t%.6e\n", alpha, 1 / beta, allreduce);
  }
  MPI_Finalize();
  return 0;
}
