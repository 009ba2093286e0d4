#pragma once
// METIS k-way partition of the global fluid-cell graph (cells connected through faces). Computed on
// rank 0 and broadcast, so every rank holds the same owner array.
#include <mpi.h>

#include <vector>

namespace parcelflow::cfd {

class Partitioner {
 public:
  // xadj/adjncy: CSR adjacency of the global cells; weights: one METIS vertex weight per cell.
  static std::vector<int> partition(MPI_Comm comm, const std::vector<int>& xadj,
                                    const std::vector<int>& adjncy, const std::vector<int>& weights);
};

}  // namespace parcelflow::cfd
