// peakMemory: after the last rank touches 200 MB more than the others, it is the largest, by at least that
// much (ru_maxrss only grows; the others stay at their own size).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cstring>
#include <vector>

#include "peak_memory.h"

using namespace parcelflow::coupling;

TEST(PeakMemory, FindsTheRankThatTouchedTheMostMemory) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const PeakMemory before = peakMemory(MPI_COMM_WORLD);
  constexpr std::size_t kBytes = 200u << 20;
  std::vector<char> block;
  if (rank == ranks - 1) {
    block.resize(kBytes);
    std::memset(block.data(), 1, kBytes);  // resident only once written
  }
  const PeakMemory after = peakMemory(MPI_COMM_WORLD);
  EXPECT_EQ(after.largest_rank, ranks - 1);
  EXPECT_GE(after.largest_mb, before.smallest_mb + 200.0);
  EXPECT_LE(after.smallest_mb, after.largest_mb);
  if (ranks > 1) {
    EXPECT_LT(after.smallest_mb, before.largest_mb + 10.0);
  }
  EXPECT_EQ(block.empty(), rank != ranks - 1);
}
