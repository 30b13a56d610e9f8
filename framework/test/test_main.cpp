// GoogleTest main for every Remnant test program: MPI initialised once, the heap set as run_main
// sets it, output from rank 0 only.
#include <gtest/gtest.h>
#include <mpi.h>

#include "remnant/heap_reuse.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  remnant::keep_freed_memory_for_reuse();  // the heap as the executables set it (run_main)
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int result = RUN_ALL_TESTS();
  int global = 0;
  MPI_Allreduce(&result, &global, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return global;
}
