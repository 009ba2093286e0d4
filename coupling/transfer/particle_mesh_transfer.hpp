#pragma once
// Generic particle -> mesh deposition and mesh -> particle gather, templated on the kernel functor
// (AMReX / MFIX-Exa style): the kernel is chosen once per batch; a TransferKernel variant is visited
// once and the loop runs on the concrete kernel.
//
// Positions are interleaved xyz (pos[3p + d]); per-parcel and per-cell quantities are interleaved with
// `ncomp` components (q[ncomp p + m], cellQ[ncomp c + m]); c is the local cell index returned by the
// lookup `localCell(i, j, k)` (owned or ghost; -1 = not a fluid cell here). Deposition ADDS into cellQ
// (ghost contributions are then summed to their owners by the gas mesh's reverse add).
//
// The lookup must return a local index for EVERY active cell within the stencil of every parcel on
// this rank (ghost layers at least R cells wide); otherwise renormalisation would drop a fluid cell on
// one rank only.
//
// Orphans (no active cell in the stencil) deposit nothing, get `orphanValue` from gather (NaN unless the
// caller chooses otherwise, e.g. 0 for the gas velocity of a parcel the integrator must still move),
// and are counted and listed in TransferStats: never silently dropped.
#include <cstddef>
#include <limits>
#include <type_traits>
#include <variant>

#include "background_grid.hpp"
#include "stencil.hpp"
#include "transfer_kernel.hpp"

namespace parcelflow::coupling {

// visit(p, const Stencil&) for every non-orphan parcel p of the batch.
template <class Kernel, class LocalCell, class Visitor>
TransferStats forEachParcelStencil(const Kernel& kernel, const BackgroundGrid& grid, LocalCell&& localCell,
                                   std::size_t n, const double* pos, Visitor&& visit) {
  if constexpr (std::is_same_v<std::decay_t<Kernel>, TransferKernel>) {
    return std::visit(
        [&](const auto& k) { return forEachParcelStencil(k, grid, localCell, n, pos, visit); }, kernel);
  } else {
    TransferStats stats;
    Stencil s;
    for (std::size_t p = 0; p < n; ++p) {
      const StencilResult r = kernel.stencil(grid, pos + 3 * p, localCell, s);
      stats.record(p, r);
      if (r != StencilResult::orphan) visit(p, static_cast<const Stencil&>(s));
    }
    return stats;
  }
}

// cellQ[ncomp c + m] += w_pc q[ncomp p + m].
template <class Kernel, class LocalCell>
TransferStats depositParcels(const Kernel& kernel, const BackgroundGrid& grid, LocalCell&& localCell,
                             std::size_t n, const double* pos, int ncomp, const double* q, double* cellQ) {
  return forEachParcelStencil(kernel, grid, localCell, n, pos, [&](std::size_t p, const Stencil& s) {
    const double* qp = q + static_cast<std::size_t>(ncomp) * p;
    for (int m = 0; m < s.size; ++m) {
      double* cq = cellQ + static_cast<std::size_t>(ncomp) * s.cell[m];
      const double w = s.weight[m];
      for (int c = 0; c < ncomp; ++c) cq[c] += w * qp[c];
    }
  });
}

// parcelQ[ncomp p + m] = sum_c w_pc cellQ[ncomp c + m]; orphans get orphanValue (default NaN).
template <class Kernel, class LocalCell>
TransferStats gatherToParcels(const Kernel& kernel, const BackgroundGrid& grid, LocalCell&& localCell,
                              std::size_t n, const double* pos, int ncomp, const double* cellQ,
                              double* parcelQ, double orphanValue = std::numeric_limits<double>::quiet_NaN()) {
  for (std::size_t i = 0; i < static_cast<std::size_t>(ncomp) * n; ++i) parcelQ[i] = orphanValue;
  return forEachParcelStencil(kernel, grid, localCell, n, pos, [&](std::size_t p, const Stencil& s) {
    double* out = parcelQ + static_cast<std::size_t>(ncomp) * p;
    for (int c = 0; c < ncomp; ++c) out[c] = 0.0;
    for (int m = 0; m < s.size; ++m) {
      const double* cq = cellQ + static_cast<std::size_t>(ncomp) * s.cell[m];
      const double w = s.weight[m];
      for (int c = 0; c < ncomp; ++c) out[c] += w * cq[c];
    }
  });
}

}  // namespace parcelflow::coupling
