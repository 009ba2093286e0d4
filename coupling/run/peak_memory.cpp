#include "coupling/run/peak_memory.h"

#include <sys/resource.h>

namespace parcelflow::coupling {

PeakMemory peakMemory(MPI_Comm comm) {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  struct {
    double value;
    int rank;
  } mine{static_cast<double>(usage.ru_maxrss) / 1024.0, rank}, largest{}, smallest{};  // Linux: kB
  MPI_Allreduce(&mine, &largest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
  MPI_Allreduce(&mine, &smallest, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
  return {largest.value, smallest.value, largest.rank};
}

}  // namespace parcelflow::coupling
