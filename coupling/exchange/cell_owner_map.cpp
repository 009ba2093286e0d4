#include "coupling/exchange/cell_owner_map.h"

#include <numeric>
#include <string>

#include "cfd/base/internal_error.hpp"

namespace parcelflow::coupling {

namespace {

std::vector<OwnedPiece> wholeCells(const std::vector<long>& owned_background_cells) {
  std::vector<OwnedPiece> pieces(owned_background_cells.size());
  for (std::size_t c = 0; c < pieces.size(); ++c) pieces[c] = {owned_background_cells[c], static_cast<int>(c), 1.0};
  return pieces;
}

// Every rank's values of one member of the pieces, in rank order.
template <class T>
std::vector<T> allGather(MPI_Comm comm, const std::vector<T>& mine, MPI_Datatype type, const std::vector<int>& counts,
                         const std::vector<int>& offsets) {
  std::vector<T> all(offsets.back() + counts.back());
  MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), type, all.data(), counts.data(), offsets.data(), type,
                 comm);
  return all;
}

}  // namespace

CellOwnerMap::CellOwnerMap(MPI_Comm comm, long background_size, const std::vector<long>& owned_background_cells)
    : CellOwnerMap(comm, background_size, wholeCells(owned_background_cells)) {}

CellOwnerMap::CellOwnerMap(MPI_Comm comm, long background_size, const std::vector<OwnedPiece>& owned_pieces)
    : comm_(comm), owner_rank_(background_size, -1), owner_index_(background_size, -1) {
  int nranks = 0;
  MPI_Comm_size(comm, &nranks);
  const int nmine = static_cast<int>(owned_pieces.size());
  std::vector<int> counts(nranks), offsets(nranks, 0);
  MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
  std::vector<long> cells(nmine);
  std::vector<int> index(nmine);
  std::vector<double> fraction(nmine);
  for (int p = 0; p < nmine; ++p) {
    cells[p] = owned_pieces[p].background_cell;
    index[p] = owned_pieces[p].owned_cell;
    fraction[p] = owned_pieces[p].fluid_fraction;
  }
  const std::vector<long> all_cells = allGather(comm, cells, MPI_LONG, counts, offsets);
  const std::vector<int> all_index = allGather(comm, index, MPI_INT, counts, offsets);
  const std::vector<double> all_fraction = allGather(comm, fraction, MPI_DOUBLE, counts, offsets);
  for (int rank = 0; rank < nranks; ++rank) {
    for (int p = offsets[rank]; p < offsets[rank] + counts[rank]; ++p) {
      const long cell = all_cells[p];
      PARCELFLOW_ASSERT(cell >= 0 && cell < background_size && owner_rank_[cell] == -1,
                        "CellOwnerMap: background cell " + std::to_string(cell) + " is out of range or owned twice");
      PARCELFLOW_ASSERT(all_fraction[p] > 0.0 && all_fraction[p] <= 1.0,
                        "CellOwnerMap: background cell " + std::to_string(cell) + " has a fluid share outside (0, 1]");
      owner_rank_[cell] = rank;
      owner_index_[cell] = all_index[p];
      if (all_fraction[p] < 1.0) cut_fraction_[cell] = all_fraction[p];
    }
  }
}

}  // namespace parcelflow::coupling
