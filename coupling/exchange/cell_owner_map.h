// Which rank owns each fluid cell of the Cartesian background, and its index there. Built once from each
// rank's list of owned cells (one all-gather of cell indices at setup, never per step); every rank can then
// route a contribution to any cell without asking anyone.
#pragma once

#include <mpi.h>

#include <vector>

namespace parcelflow::coupling {

class CellOwnerMap {
 public:
  // `owned_background_cells[c]` is the background (linear) index of this rank's owned cell c.
  CellOwnerMap(MPI_Comm comm, long background_size, const std::vector<long>& owned_background_cells);

  // -1 where the background cell is not a fluid cell.
  int ownerRank(long background_cell) const { return owner_rank_[background_cell]; }
  int ownerIndex(long background_cell) const { return owner_index_[background_cell]; }
  long backgroundSize() const { return static_cast<long>(owner_rank_.size()); }
  MPI_Comm comm() const { return comm_; }

 private:
  MPI_Comm comm_;
  std::vector<int> owner_rank_;
  std::vector<int> owner_index_;
};

}  // namespace parcelflow::coupling
