#pragma once
// The Cartesian background the gas mesh is built on: origin, uniform spacing per axis, cell counts.
// Background cell (i, j, k) spans [o + i h, o + (i+1) h) per axis; its centre is o + (i + 1/2) h.
// Which background cells are fluid, and where they live on this rank, is answered by the gas solver's
// `int localCellOfBackground(int i, int j, int k) const` (local index of an owned or ghost fluid
// cell, or -1), passed to the kernels as any callable `int(int, int, int)`.
#include <array>

namespace parcelflow::coupling {

struct BackgroundGrid {
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 3> spacing{1.0, 1.0, 1.0};
  std::array<int, 3> cells{0, 0, 0};

  double cellCentre(int axis, int index) const { return origin[axis] + (index + 0.5) * spacing[axis]; }
  // Throws std::invalid_argument on non-positive spacing or cell counts.
  void validate() const;
};

}  // namespace parcelflow::coupling
