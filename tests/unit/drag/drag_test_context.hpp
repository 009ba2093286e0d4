#pragma once
// The per-case constants the drag tests give makeDragLaw: what the filtered law needs (the others ignore
// them), here FCC in 75 mm cells unless a filter size is given.
#include "coupling/drag/drag_input.hpp"

namespace parcelflow::coupling::test {

inline DragLawContext fccContext(double filterSize = 0.075) {
  DragLawContext c;
  c.filterSize = filterSize;
  c.gravity = 9.81;
  c.particleDensity = 1500.0;
  return c;
}

}  // namespace parcelflow::coupling::test
