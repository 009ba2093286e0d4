#pragma once
// The Cartesian background the gas mesh is built on: origin, uniform spacing per axis, cell counts.
// Background cell (i, j, k) spans [o + i h, o + (i+1) h) per axis; its centre is o + (i + 1/2) h.
// Which cells are fluid is the caller's answer (FluidCells in box_stencils.hpp; the coupler counts a
// cell as fluid when some rank owns it), so the weights do not depend on the partition.
#include <array>

namespace parcelflow::coupling {

struct BackgroundGrid {
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 3> spacing{1.0, 1.0, 1.0};
  std::array<int, 3> cells{0, 0, 0};

  double cellCentre(int axis, int index) const { return origin[axis] + (index + 0.5) * spacing[axis]; }
  // Requires positive spacing and cell counts (PARCELFLOW_ASSERT).
  void validate() const;
};

}  // namespace parcelflow::coupling
