// The largest resident memory a rank has used so far (getrusage's ru_maxrss), over the ranks: what a user
// sizes a machine by. Collective: two reductions of one (value, rank) pair.
#pragma once

#include <mpi.h>

namespace parcelflow::coupling {

struct PeakMemory {
  double largest_mb = 0.0, smallest_mb = 0.0;
  int largest_rank = 0;
};

PeakMemory peakMemory(MPI_Comm comm);

}  // namespace parcelflow::coupling
