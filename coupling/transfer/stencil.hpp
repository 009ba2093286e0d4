#pragma once
// The cells and weights one parcel exchanges with: local cell indices (as returned by the gas mesh's
// lookup, owned or ghost) and weights that sum to 1 over them.
#include <cstddef>
#include <vector>

namespace parcelflow::coupling {

struct Stencil {
  static constexpr int capacity = 729;  // (2R + 1)^3 for the largest allowed radius R = 4
  int size = 0;
  int cell[capacity];
  double weight[capacity];
};

enum class StencilResult : unsigned char {
  ok,        // weights found in the regular stencil
  fallback,  // centroid kernel: containing cell not active/not present, nearest active cell used
  orphan     // no active cell reachable: the parcel exchanges nothing (counted and listed)
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
