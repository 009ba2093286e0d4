#pragma once
// Test oracle: particle <-> mesh transfer the way it ran when parcels deposited into the gas mesh's
// ghost layers. Each parcel's kernel window is expanded to (local cell, weight) pairs through a lookup
// int(i, j, k) -> local index (owned or ghost) or -1, and renormalised over the cells the lookup knows;
// deposit adds into local cells, gather reads them. It shares only the kernels' windows with the box
// stencils the coupler uses (coupling/transfer/box_stencils.hpp), so the transfer tests compare the two
// and the transfer benchmark times it as the uncached baseline.
#include <cstddef>
#include <limits>
#include <type_traits>
#include <variant>

#include "coupling/transfer/background_grid.hpp"
#include "coupling/transfer/stencil.hpp"
#include "coupling/transfer/transfer_kernel.hpp"

namespace parcelflow::coupling::test {

// A window expanded to local cells, weights summing to 1 over them.
struct Stencil {
  static constexpr int capacity = Window::maxWidth * Window::maxWidth * Window::maxWidth;
  int size = 0;
  int cell[capacity];
  double weight[capacity];
};

// The stencil of a parcel at x for a concrete kernel; a cell is fluid if the lookup knows it.
template <class Kernel, class LocalCell>
StencilResult stencilOf(const Kernel& kernel, const BackgroundGrid& g, const double* x, const LocalCell& localCell,
                        Stencil& s, double diameter = 0.0) {
  s.size = 0;
  Window w;
  const auto fluidShare = [&](int i, int j, int k) { return localCell(i, j, k) >= 0 ? 1.0 : 0.0; };
  const StencilResult r = kernel.window(g, x, diameter, fluidShare, w);
  if (r == StencilResult::orphan) return r;
  double sum = 0.0;
  for (int c = 0; c < w.n[2]; ++c)
    for (int b = 0; b < w.n[1]; ++b)
      for (int a = 0; a < w.n[0]; ++a) {
        const int cell = localCell(w.lo[0] + a, w.lo[1] + b, w.lo[2] + c);
        if (cell < 0) continue;
        s.cell[s.size] = cell;
        s.weight[s.size] = w.f[0][a] * w.f[1][b] * w.f[2][c];
        sum += s.weight[s.size];
        ++s.size;
      }
  if (s.size == 0) return StencilResult::orphan;
  const double inverseSum = 1.0 / sum;
  for (int m = 0; m < s.size; ++m) s.weight[m] *= inverseSum;
  return r;
}

// visit(p, const Stencil&) for every non-orphan parcel p of the batch.
template <class Kernel, class LocalCell, class Visitor>
TransferStats forEachParcelStencil(const Kernel& kernel, const BackgroundGrid& grid, const LocalCell& localCell,
                                   std::size_t n, const double* pos, Visitor&& visit) {
  if constexpr (std::is_same_v<std::decay_t<Kernel>, TransferKernel>) {
    return std::visit(
        [&](const auto& k) { return forEachParcelStencil(k, grid, localCell, n, pos, visit); }, kernel);
  } else {
    TransferStats stats;
    Stencil s;
    for (std::size_t p = 0; p < n; ++p) {
      const StencilResult r = stencilOf(kernel, grid, pos + 3 * p, localCell, s);
      stats.record(p, r);
      if (r != StencilResult::orphan) visit(p, static_cast<const Stencil&>(s));
    }
    return stats;
  }
}

// cellQ[ncomp c + m] += w_pc q[ncomp p + m] (c: local cell index).
template <class Kernel, class LocalCell>
TransferStats depositParcels(const Kernel& kernel, const BackgroundGrid& grid, const LocalCell& localCell,
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

// parcelQ[ncomp p + m] = sum_c w_pc cellQ[ncomp c + m]; orphans get orphanValue.
template <class Kernel, class LocalCell>
TransferStats gatherToParcels(const Kernel& kernel, const BackgroundGrid& grid, const LocalCell& localCell,
                              std::size_t n, const double* pos, int ncomp, const double* cellQ, double* parcelQ,
                              double orphanValue = std::numeric_limits<double>::quiet_NaN()) {
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

}  // namespace parcelflow::coupling::test
