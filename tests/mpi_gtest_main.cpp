// The GoogleTest main of every test that runs under mpirun: MPI is initialised around all tests, only
// rank 0 prints GoogleTest's progress, and a failure on any rank fails the process. stdout is line
// buffered because LIGGGHTS errors end the process.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstdio>

#include "cfd/io/mpi_io_defaults.hpp"

int main(int argc, char** argv) {
  parcelflow::cfd::preferRomioForMpiIo();  // as the parcelflow program does
  MPI_Init(&argc, &argv);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int result = RUN_ALL_TESTS();
  int worst = 0;
  MPI_Allreduce(&result, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return worst;
}
