#pragma once
// Gaussian particle <-> mesh kernel (paper eq. 8; DESIGN.md section 4).
// Reference: Braun, Srinivasa, Gohel, "Validation of an efficient CFD-DEM model for large scale
// fluidized beds", eq. (8), after Apte (2008) and Kaufmann (2008):
//   w ~ exp(-a |x_cell - x_p|^2 / h^2),  a = 1 by default.
// On the Cartesian background the kernel is separable: w = fx fy fz with fx = exp(-a dx^2 / hx^2)
// (h per axis). It is truncated to +-R cells per axis around the cell containing the parcel (R = 2 by
// default, at most 4) and renormalised over the ACTIVE cells of that stencil (those the lookup maps to
// a local index), so sum w = 1 exactly: volume and momentum are conserved also next to walls. The
// prefactor (a/pi)^1.5 of eq. 8 cancels in the renormalisation.
#include <cmath>

#include "background_grid.hpp"
#include "stencil.hpp"

namespace parcelflow::coupling {

class GaussianKernel {
 public:
  static constexpr const char* typeName = "gaussian";
  static constexpr int maxRadius = 4;
  static_assert((2 * maxRadius + 1) * (2 * maxRadius + 1) * (2 * maxRadius + 1) <= Stencil::capacity);

  // Throws std::invalid_argument unless a > 0 and 0 <= radius <= maxRadius.
  explicit GaussianKernel(double sharpness = 1.0, int radius = 2);

  double sharpness() const { return a_; }
  int radius() const { return r_; }

  // Mass fraction of the untruncated 1-D lattice kernel (all cells of an infinite row) that lies in
  // the +-R stencil, for a parcel at `offset` cell lengths from the centre of its cell (|offset| <= 1/2).
  // The 3-D fraction is the product over the axes.
  static double retainedMassFraction1D(double sharpness, int radius, double offset);

  template <class LocalCell>
  StencilResult stencil(const BackgroundGrid& g, const double* x, LocalCell& localCell, Stencil& s) const {
    s.size = 0;
    constexpr int width = 2 * maxRadius + 1;
    double f[3][width];
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      const double xi = (x[d] - g.origin[d]) / g.spacing[d];  // position in cell units
      // also rejects NaN: no stencil cell can exist beyond R cells outside the box
      if (!(xi > -r_ - 1.0 && xi < g.cells[d] + r_ + 1.0)) return StencilResult::orphan;
      const int ic = static_cast<int>(std::floor(xi));
      lo[d] = ic - r_ < 0 ? 0 : ic - r_;
      hi[d] = ic + r_ > g.cells[d] - 1 ? g.cells[d] - 1 : ic + r_;
      if (lo[d] > hi[d]) return StencilResult::orphan;
      for (int i = lo[d]; i <= hi[d]; ++i) {
        const double t = (i + 0.5) - xi;
        f[d][i - lo[d]] = std::exp(-a_ * t * t);
      }
    }
    double sum = 0.0;
    for (int k = lo[2]; k <= hi[2]; ++k) {
      const double fz = f[2][k - lo[2]];
      for (int j = lo[1]; j <= hi[1]; ++j) {
        const double fyz = f[1][j - lo[1]] * fz;
        for (int i = lo[0]; i <= hi[0]; ++i) {
          const int c = localCell(i, j, k);
          if (c < 0) continue;
          const double w = f[0][i - lo[0]] * fyz;
          s.cell[s.size] = c;
          s.weight[s.size] = w;
          ++s.size;
          sum += w;
        }
      }
    }
    if (s.size == 0) return StencilResult::orphan;
    for (int m = 0; m < s.size; ++m) s.weight[m] /= sum;
    return StencilResult::ok;
  }

 private:
  double a_;
  int r_;
};

}  // namespace parcelflow::coupling
