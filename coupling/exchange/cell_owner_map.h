// Which rank owns each fluid cell of the Cartesian background, its index there and its fluid share. Built
// once from each rank's owned cells (one all-gather at setup, never per step); every rank can then route a
// contribution to any cell without asking anyone. On a cut-cell mesh a gas cell is one background cell cut
// by a wall (fluid share below 1), or several merged ones: each of them routes to the gas cell they make.
#pragma once

#include <mpi.h>

#include <unordered_map>
#include <vector>

namespace parcelflow::coupling {

// One background cell of an owned gas cell.
struct OwnedPiece {
  long background_cell = 0;
  int owned_cell = 0;            // the gas cell's index among this rank's owned cells
  double fluid_fraction = 1.0;   // its fluid volume over the background cell's volume, in (0, 1]
};

class CellOwnerMap {
 public:
  // `owned_background_cells[c]` is the background (linear) index of this rank's owned cell c (whole cells).
  CellOwnerMap(MPI_Comm comm, long background_size, const std::vector<long>& owned_background_cells);
  // Every background cell of this rank's owned gas cells.
  CellOwnerMap(MPI_Comm comm, long background_size, const std::vector<OwnedPiece>& owned_pieces);

  // -1 where the background cell is not a fluid cell.
  int ownerRank(long background_cell) const { return owner_rank_[background_cell]; }
  int ownerIndex(long background_cell) const { return owner_index_[background_cell]; }
  // 0 where no fluid, 1 for whole fluid cells, between for cells cut by a wall.
  double fluidFraction(long background_cell) const {
    if (owner_rank_[background_cell] < 0) return 0.0;
    const auto cut = cut_fraction_.find(background_cell);
    return cut == cut_fraction_.end() ? 1.0 : cut->second;
  }
  long backgroundSize() const { return static_cast<long>(owner_rank_.size()); }
  MPI_Comm comm() const { return comm_; }

 private:
  MPI_Comm comm_;
  std::vector<int> owner_rank_;
  std::vector<int> owner_index_;
  std::unordered_map<long, double> cut_fraction_;  // only the cells with a share below 1 (a wall's surface)
};

}  // namespace parcelflow::coupling
