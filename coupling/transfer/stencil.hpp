#pragma once
// What a kernel gives one parcel. A Window: a box of background cells and per-axis factors, so cell
// (lo[0] + a, lo[1] + b, lo[2] + c) weighs f[0][a] f[1][b] f[2][c] before the weights are renormalised
// over the window's fluid cells (every kernel here is separable on the Cartesian background). A Stencil:
// the window expanded to local cell indices (as returned by the gas mesh's lookup, owned or ghost) and
// weights that sum to 1 over them.
#include <cstddef>
#include <vector>

namespace parcelflow::coupling {

struct Window {
  static constexpr int maxWidth = 9;  // 2R + 1 for the largest allowed radius R = 4
  int lo[3];
  int n[3];
  double f[3][maxWidth];
};

struct Stencil {
  static constexpr int capacity = Window::maxWidth * Window::maxWidth * Window::maxWidth;
  int size = 0;
  int cell[capacity];
  double weight[capacity];
};

enum class StencilResult : unsigned char {
  ok,        // weights found in the regular stencil
  fallback,  // centroid kernel: containing cell not active/not present, nearest active cell used
  orphan     // no active cell reachable: the parcel exchanges nothing (counted and listed)
};

// The window's fluid cells (localCell(i, j, k) >= 0) and their renormalised weights; orphan if none.
template <class LocalCell>
StencilResult expandWindow(const Window& w, StencilResult r, LocalCell& localCell, Stencil& s) {
  s.size = 0;
  if (r == StencilResult::orphan) return r;
  // The lookup may allocate (a new touched cell), so nothing is accumulated across it: collect the
  // fluid cells and their unnormalised weights first, sum afterwards.
  int n = 0;
  for (int c = 0; c < w.n[2]; ++c)
    for (int b = 0; b < w.n[1]; ++b)
      for (int a = 0; a < w.n[0]; ++a) {
        const int cell = localCell(w.lo[0] + a, w.lo[1] + b, w.lo[2] + c);
        if (cell < 0) continue;
        s.cell[n] = cell;
        s.weight[n] = w.f[0][a] * w.f[1][b] * w.f[2][c];
        ++n;
      }
  s.size = n;
  if (n == 0) return StencilResult::orphan;
  double sum = 0.0;
  for (int m = 0; m < n; ++m) sum += s.weight[m];
  const double inverseSum = 1.0 / sum;
  for (int m = 0; m < n; ++m) s.weight[m] *= inverseSum;
  return r;
}

// Counters of one transfer pass; orphans are listed so the caller can report them by parcel.
struct TransferStats {
  std::size_t parcels = 0;
  std::size_t fallbacks = 0;
  std::size_t orphans = 0;
  std::vector<std::size_t> orphanParcels;  // batch indices of the orphans

  void record(std::size_t parcel, StencilResult r) {
    ++parcels;
    if (r == StencilResult::fallback) ++fallbacks;
    if (r == StencilResult::orphan) {
      ++orphans;
      orphanParcels.push_back(parcel);
    }
  }
};

}  // namespace parcelflow::coupling
