// Many-to-many exchange between the ranks that hold parcels and the ranks that own the cells they touch
// (DESIGN section 7): contributions are summed into the owners' cells, and owned cell values are fetched
// back over the same pattern. setCells() routes a set of cells once (one all-to-all of counts, one
// integer per rank pair, and one all-to-all-v of their owner-local indices); every transfer over that set
// then costs one all-to-all-v of exactly its values: no all-reduce over particles or cells.
#pragma once

#include <vector>

#include "coupling/exchange/cell_owner_map.h"

namespace parcelflow::coupling {

class CellExchange {
 public:
  explicit CellExchange(const CellOwnerMap& owners) : owners_(owners) {}

  // The cells of the following transfers: fluid background cells, each listed once per rank. Collective.
  void setCells(const std::vector<long>& cells);

  // Adds `values[t*width .. t*width+width)` into row ownerIndex(cells[t]) of `owned` (nOwned x width,
  // row-major) on the owning rank.
  void sumToOwners(const std::vector<double>& values, int width, std::vector<double>& owned) const;

  // The reverse: `out[t*width ..]` = row ownerIndex(cells[t]) of the owner's `owned`.
  void fetchFromOwners(const std::vector<double>& owned, int width, std::vector<double>& out) const;

 private:
  struct Routing {
    std::vector<int> send_counts, send_offsets, recv_counts, recv_offsets;
    std::vector<int> order;           // cell positions sorted by destination rank
    std::vector<int> remote_index;    // owner-local indices of the cells this rank receives
    std::vector<int> send_index;      // setCells' owner-local indices in send order
  };
  // The counts and offsets of one transfer of `width` values per cell, in the scratch below.
  void scaleCounts(int width) const;
  const CellOwnerMap& owners_;
  Routing route_;
  // Reused by every transfer (each coupling step runs several): no allocation once they have grown.
  mutable std::vector<double> send_, recv_;
  mutable std::vector<int> counts_[4];  // send counts, send offsets, recv counts, recv offsets x width
};

}  // namespace parcelflow::coupling
