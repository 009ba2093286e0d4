// peakMemory: after the last rank touches 200 MiB more than the others, it is the largest, and its peak is at
// least its resident size just before plus those 200 MiB (ru_maxrss only grows; the others stay at their own
// size). The bound starts from the resident size, not from the peak before: memory freed earlier (MPI's
// start-up) leaves the peak above the resident size, and the new block first fills that gap. Both numbers
// come from Linux's resident-page counters, which each thread updates in batches of 64 page faults
// (0.25 MiB of 4 KiB pages): measured 0.09 MiB short of the exact sum, so the bound allows 1 MiB
// (4 threads' batches), against the 200 MiB that are tested.
#include <gtest/gtest.h>
#include <mpi.h>

#include <unistd.h>

#include <cstring>
#include <fstream>
#include <vector>

#include "coupling/run/peak_memory.h"

using namespace parcelflow::coupling;

namespace {

// This process's resident size now [MiB] (/proc/self/statm: total and resident pages).
double residentMb() {
  std::ifstream statm("/proc/self/statm");
  long total = 0, resident = 0;
  statm >> total >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

}  // namespace

TEST(PeakMemory, FindsTheRankThatTouchedTheMostMemory) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const PeakMemory before = peakMemory(MPI_COMM_WORLD);
  constexpr std::size_t kBytes = 200u << 20;
  std::vector<char> block;
  double resident_before = 0.0;
  if (rank == ranks - 1) {
    resident_before = residentMb();
    EXPECT_GT(resident_before, 0.0);
    block.resize(kBytes);
    std::memset(block.data(), 1, kBytes);  // resident only once written
  }
  const PeakMemory after = peakMemory(MPI_COMM_WORLD);
  EXPECT_EQ(after.largest_rank, ranks - 1);
  if (rank == ranks - 1) {
    EXPECT_GE(after.largest_mb, resident_before + 200.0 - 1.0);
  }
  EXPECT_LE(after.smallest_mb, after.largest_mb);
  if (ranks > 1) {
    EXPECT_LT(after.smallest_mb, before.largest_mb + 10.0);
  }
  EXPECT_EQ(block.empty(), rank != ranks - 1);
}
