// Many-to-many exchange between the ranks that hold parcels and the ranks that own the cells they touch
// (DESIGN section 7): contributions are summed into the owners' cells, and owned cell values are fetched
// back over the same pattern. setCells() routes a set of cells once (one all-to-all of counts, one
// integer per rank pair, and one all-to-all-v of their owner-local indices); every transfer over that set
// then costs one all-to-all-v of exactly its values: no all-reduce over particles or cells.
#pragma once

#include <vector>

#include "cell_owner_map.h"

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
  };
  const CellOwnerMap& owners_;
  Routing route_;
};

}  // namespace parcelflow::coupling
