#pragma once
// Cell-centroid ("particle source in cell") kernel: all of a parcel's weight goes to the background
// cell containing it. If that cell is not fluid (a parcel overlapping a wall, or outside the box), the
// nearest fluid cell (by distance to its centre) within +-searchRadius cells is used and the parcel is
// counted as a fallback; if there is none it is an orphan (counted and listed).
// Reference: MFIX-Exa "centroid" deposition scheme; Crowe et al., PSI-CELL, J. Fluids Eng. 99 (1977).
#include <cmath>

#include "coupling/transfer/background_grid.hpp"
#include "coupling/transfer/stencil.hpp"

namespace parcelflow::coupling {

class CentroidKernel {
 public:
  static constexpr const char* typeName = "centroid";
  static constexpr int maxSearchRadius = 3;

  // Requires 0 <= searchRadius <= maxSearchRadius (PARCELFLOW_ASSERT).
  explicit CentroidKernel(int searchRadius = 1);

  int searchRadius() const { return r_; }
  bool readsDiameter() const { return false; }

  // One cell with factor 1: the containing one if it is fluid (fluidShare(i, j, k) > 0), else the nearest
  // fluid cell within +-searchRadius (fallback), else none (orphan). The parcel's diameter is not read.
  template <class FluidShare>
  StencilResult window(const BackgroundGrid& g, const double* x, double /*diameter*/, const FluidShare& fluidShare,
                       Window& w) const {
    int ic[3];
    bool inside = true;
    for (int d = 0; d < 3; ++d) {
      const double xi = (x[d] - g.origin[d]) / g.spacing[d];
      if (!(xi > -r_ - 1.0 && xi < g.cells[d] + r_ + 1.0)) return StencilResult::orphan;  // also NaN
      int i = static_cast<int>(std::floor(xi));
      if (i < 0 || i >= g.cells[d]) {
        inside = false;
        i = i < 0 ? 0 : g.cells[d] - 1;
      }
      ic[d] = i;
    }
    if (inside && fluidShare(ic[0], ic[1], ic[2]) > 0.0) {
      setCell(ic, w);
      return StencilResult::ok;
    }
    double best = 0.0;
    int bestCell[3] = {-1, -1, -1};
    for (int k = ic[2] - r_; k <= ic[2] + r_; ++k) {
      if (k < 0 || k >= g.cells[2]) continue;
      for (int j = ic[1] - r_; j <= ic[1] + r_; ++j) {
        if (j < 0 || j >= g.cells[1]) continue;
        for (int i = ic[0] - r_; i <= ic[0] + r_; ++i) {
          if (i < 0 || i >= g.cells[0] || !(fluidShare(i, j, k) > 0.0)) continue;
          const double dx = g.cellCentre(0, i) - x[0], dy = g.cellCentre(1, j) - x[1],
                       dz = g.cellCentre(2, k) - x[2];
          const double dist2 = dx * dx + dy * dy + dz * dz;
          if (bestCell[0] < 0 || dist2 < best) {
            best = dist2;
            bestCell[0] = i;
            bestCell[1] = j;
            bestCell[2] = k;
          }
        }
      }
    }
    if (bestCell[0] < 0) return StencilResult::orphan;
    setCell(bestCell, w);
    return StencilResult::fallback;
  }

 private:
  static void setCell(const int ijk[3], Window& w) {
    for (int d = 0; d < 3; ++d) {
      w.lo[d] = ijk[d];
      w.n[d] = 1;
      w.f[d][0] = 1.0;
    }
  }

  int r_;
};

}  // namespace parcelflow::coupling
