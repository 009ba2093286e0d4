#pragma once
// What a kernel gives one parcel: a Window, a box of background cells and per-axis factors, so cell
// (lo[0] + a, lo[1] + b, lo[2] + c) weighs f[0][a] f[1][b] f[2][c] before the weights are renormalised
// over the window's fluid cells (every kernel here is separable on the Cartesian background).
#include <cstddef>
#include <vector>

namespace parcelflow::coupling {

struct Window {
  static constexpr int maxWidth = 9;  // 2R + 1 for the largest allowed radius R = 4
  int lo[3];
  int n[3];
  double f[3][maxWidth];
};

enum class StencilResult : unsigned char {
  ok,        // the kernel's regular window
  fallback,  // centroid kernel: containing cell not fluid, nearest fluid cell used
  orphan     // no fluid cell in the window: the parcel exchanges nothing (counted and listed)
};

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
