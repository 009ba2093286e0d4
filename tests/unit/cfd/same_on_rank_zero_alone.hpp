#pragma once
// The check that a collective operation gives the same cell field on any number of ranks: the field of the
// run on all ranks by global cell id, and rank 0 alone on a communicator of its own.
#include <mpi.h>

#include <vector>

#include "cfd/mesh/mesh.hpp"

namespace parcelflow::cfd::test {

// Every cell's value by global id on every rank (each cell is owned once, so the sum is the value).
inline std::vector<double> byGlobalId(const Mesh& m, const std::vector<double>& owned) {
  std::vector<double> global(m.nGlobalCells(), 0.0);
  for (int c = 0; c < m.nOwnedCells(); ++c) global[m.globalId(c)] = owned[c];
  MPI_Allreduce(MPI_IN_PLACE, global.data(), static_cast<int>(global.size()), MPI_DOUBLE, MPI_SUM, m.comm());
  return global;
}

// Calls alone(comm) on rank 0 with a communicator holding rank 0 only. Collective over MPI_COMM_WORLD.
template <class Alone>
void onRankZeroAlone(const Alone& alone) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm self;
  MPI_Comm_split(MPI_COMM_WORLD, rank, 0, &self);
  if (rank == 0) alone(self);
  MPI_Comm_free(&self);
}

}  // namespace parcelflow::cfd::test
