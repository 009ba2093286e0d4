#include "cell_owner_map.h"

#include <numeric>
#include <stdexcept>
#include <string>

#include "cfd/internal_error.hpp"

namespace parcelflow::coupling {

CellOwnerMap::CellOwnerMap(MPI_Comm comm, long background_size, const std::vector<long>& owned_background_cells)
    : comm_(comm), owner_rank_(background_size, -1), owner_index_(background_size, -1) {
  int nranks = 0;
  MPI_Comm_size(comm, &nranks);
  const int nowned = static_cast<int>(owned_background_cells.size());
  std::vector<int> counts(nranks), offsets(nranks, 0);
  MPI_Allgather(&nowned, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
  std::vector<long> all(offsets.back() + counts.back());
  MPI_Allgatherv(owned_background_cells.data(), nowned, MPI_LONG, all.data(), counts.data(), offsets.data(),
                 MPI_LONG, comm);
  for (int rank = 0; rank < nranks; ++rank) {
    for (int c = 0; c < counts[rank]; ++c) {
      const long cell = all[offsets[rank] + c];
      PARCELFLOW_ASSERT(cell >= 0 && cell < background_size && owner_rank_[cell] == -1,
                        "CellOwnerMap: background cell " + std::to_string(cell) + " is out of range or owned twice");
      owner_rank_[cell] = rank;
      owner_index_[cell] = c;
    }
  }
}

}  // namespace parcelflow::coupling
