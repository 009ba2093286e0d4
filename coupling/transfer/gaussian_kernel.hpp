#pragma once
// Gaussian particle <-> mesh kernel (paper eq. 8; DESIGN.md section 4).
// Reference: Braun, Srinivasa, Gohel, "Validation of an efficient CFD-DEM model for large scale
// fluidized beds", eq. (8), after Apte (2008) and Kaufmann (2008):
//   w ~ exp(-a |x_cell - x_p|^2 / h^2),  a = 1 by default.
// On the Cartesian background the kernel is separable: w = fx fy fz with fx = exp(-a_x tx^2), tx = dx / hx
// the distance in cell lengths of that axis. h is one length, the cube root of the cell volume (the
// paper's "characteristic length scale of the cell"; case default): a_x = a (hx / h)^2, the same width in
// metres along every axis; or the cell's length along each axis (a_x = a: as many cells wide along every
// axis, so tall cells smooth vertically over more metres). The two agree on cubic cells. The kernel is
// truncated to +-R cells per axis around the cell containing the parcel (R = 2 by default, at most 4); the
// box stencils renormalise it over the fluid cells of that window, so sum w = 1 exactly: volume and
// momentum are conserved also next to walls. The prefactor (a/pi)^1.5 of eq. 8 cancels in the
// renormalisation.
#include <cmath>

#include "background_grid.hpp"
#include "stencil.hpp"

namespace parcelflow::coupling {

class GaussianKernel {
 public:
  static constexpr const char* typeName = "gaussian";
  static constexpr int maxRadius = 4;
  static_assert(2 * maxRadius + 1 <= Window::maxWidth);

  // h per axis. Requires a > 0 and 0 <= radius <= maxRadius (PARCELFLOW_ASSERT).
  explicit GaussianKernel(double sharpness = 1.0, int radius = 2);
  // h = (hx hy hz)^(1/3) of cells of `spacing` (each > 0).
  GaussianKernel(double sharpness, int radius, const double (&spacing)[3]);

  double sharpness() const { return a_; }
  // a_d: the sharpness along axis d in that axis' cell lengths
  double axisSharpness(int d) const { return axisA_[d]; }
  int radius() const { return r_; }

  // Mass fraction of the untruncated 1-D lattice kernel (all cells of an infinite row) that lies in
  // the +-R stencil, for a parcel at `offset` cell lengths from the centre of its cell (|offset| <= 1/2).
  // The 3-D fraction is the product over the axes.
  static double retainedMassFraction1D(double sharpness, int radius, double offset);

  // The window of a parcel at x: +-R cells around its cell, clipped to the background (fluid or not:
  // the renormalisation over fluid cells is the caller's, so isFluid is not read); orphan beyond R cells
  // outside the box.
  template <class IsFluid>
  StencilResult window(const BackgroundGrid& g, const double* x, const IsFluid&, Window& w) const {
    for (int d = 0; d < 3; ++d) {
      const double xi = (x[d] - g.origin[d]) / g.spacing[d];  // position in cell units
      // also rejects NaN: no stencil cell can exist beyond R cells outside the box
      if (!(xi > -r_ - 1.0 && xi < g.cells[d] + r_ + 1.0)) return StencilResult::orphan;
      const int ic = static_cast<int>(std::floor(xi));
      const int lo = ic - r_ < 0 ? 0 : ic - r_;
      const int hi = ic + r_ > g.cells[d] - 1 ? g.cells[d] - 1 : ic + r_;
      if (lo > hi) return StencilResult::orphan;
      w.lo[d] = lo;
      w.n[d] = hi - lo + 1;
      // exp(-a t^2) at t = t0 + m, m = -R..R, from the centre outwards with 3 exponentials: the ratio of
      // neighbours is exp(-a (2 t + 1)) upwards, and each ratio is exp(-2a) times the previous one.
      // All ratios are <= 1 (|t0| <= 1/2), so far factors underflow to 0 as exp itself would.
      const double t0 = (ic + 0.5) - xi, a = axisA_[d];
      double f[Window::maxWidth];
      f[r_] = std::exp(-a * t0 * t0);
      double up = std::exp(-a * (2.0 * t0 + 1.0)), down = std::exp(-a * (1.0 - 2.0 * t0));
      for (int m = 1; m <= r_; ++m) {
        f[r_ + m] = f[r_ + m - 1] * up;
        f[r_ - m] = f[r_ - m + 1] * down;
        up *= expMinus2a_[d];
        down *= expMinus2a_[d];
      }
      for (int i = lo; i <= hi; ++i) w.f[d][i - lo] = f[i - ic + r_];
    }
    return StencilResult::ok;
  }

 private:
  double a_;
  int r_;
  double axisA_[3], expMinus2a_[3];
};

}  // namespace parcelflow::coupling
