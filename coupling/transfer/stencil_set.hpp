#pragma once
// The stencils of a whole batch of parcels, computed once per coupling step and reused for every
// transfer of that step (deposit volume, gather a_g, u, grad p, deposit kappa and kappa v): the same
// weights both ways, so the force on the gas is minus the force on the parcels to round-off.
// Storage is compressed rows: parcel p uses entries offset[p] .. offset[p+1]-1 (empty for orphans).
#include <cstddef>
#include <limits>
#include <vector>

#include "particle_mesh_transfer.hpp"

namespace parcelflow::coupling {

struct StencilSet {
  std::vector<std::size_t> offset{0};  // size parcels() + 1
  std::vector<int> cell;               // local cell indices
  std::vector<double> weight;          // sum to 1 per non-orphan parcel

  std::size_t parcels() const { return offset.size() - 1; }
  void clear() {
    offset.assign(1, 0);
    cell.clear();
    weight.clear();
  }
};

template <class Kernel, class LocalCell>
TransferStats buildStencils(const Kernel& kernel, const BackgroundGrid& grid, LocalCell&& localCell,
                            std::size_t n, const double* pos, StencilSet& out) {
  out.clear();
  out.offset.assign(n + 1, 0);
  std::size_t done = 0;  // parcels whose offset[p + 1] is set
  TransferStats stats =
      forEachParcelStencil(kernel, grid, localCell, n, pos, [&](std::size_t p, const Stencil& s) {
        for (; done < p; ++done) out.offset[done + 1] = out.cell.size();  // orphans before p: empty
        out.cell.insert(out.cell.end(), s.cell, s.cell + s.size);
        out.weight.insert(out.weight.end(), s.weight, s.weight + s.size);
        out.offset[p + 1] = out.cell.size();
        done = p + 1;
      });
  for (; done < n; ++done) out.offset[done + 1] = out.cell.size();
  return stats;
}

// cellQ[ncomp c + m] += w_pc q[ncomp p + m].
void deposit(const StencilSet& set, int ncomp, const double* q, double* cellQ);

// parcelQ[ncomp p + m] = sum_c w_pc cellQ[ncomp c + m]; orphans (empty rows) get orphanValue.
void gather(const StencilSet& set, int ncomp, const double* cellQ, double* parcelQ,
            double orphanValue = std::numeric_limits<double>::quiet_NaN());

}  // namespace parcelflow::coupling
