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
// Parcels larger than the cell (coarse graining): with a parcel factor lambda > 0 a parcel of collision
// diameter D is spread over at least its own size, h_p = max(h, lambda D) along each axis, with the
// window widened in proportion (R_p = ceil(R h_p / h), at most maxRadius) so that it truncates the wider
// Gaussian as R truncates the cell's. A parcel of 2 cell volumes otherwise lands in 1-2 cells, and the
// gas-fraction floor is hit where they touch (cases/goldschmidt_segregation/README.md, "Coarse graining:
// causes"). lambda = 0 is eq. 8 as the paper wrote it; parcels with lambda D <= h are unaffected either way.
// Reflecting faces: the part of the Gaussian beyond a face of the background box is folded back onto the
// mirror cells (an image parcel behind the face) instead of being dropped before the renormalisation. Evenly
// spread parcel centres then deposit evenly up to the face, where truncation piles up 11 % more volume
// (tests/unit/transfer/deposition_test.cpp). In the settled Goldschmidt bed, whose centres keep D/2 off the
// walls, the wall cells get 0.87 of the middle cells' bead volume truncated, 0.94 reflected, and the beads
// themselves put 0.93 there. Faces of the box only: cells blocked by the geometry inside it still truncate.
#include <algorithm>
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
  // Either length scale, parcels wider than lambda D = h spread over h_p = lambda D (lambda >= 0), and the
  // background's faces reflecting (image parcels) or truncating the kernel.
  GaussianKernel(double sharpness, int radius, const double (&spacing)[3], bool isotropic, double parcelFactor,
                 bool reflectAtFaces = false);

  double sharpness() const { return a_; }
  // a_d: the sharpness along axis d in that axis' cell lengths
  double axisSharpness(int d) const { return axisA_[d]; }
  int radius() const { return r_; }
  double parcelFactor() const { return parcelFactor_; }
  // whether window() reads the parcel's diameter (only to widen the kernel for large parcels)
  bool readsDiameter() const { return parcelFactor_ > 0.0; }
  bool reflectsAtFaces() const { return reflect_; }

  // Mass fraction of the untruncated 1-D lattice kernel (all cells of an infinite row) that lies in
  // the +-R stencil, for a parcel at `offset` cell lengths from the centre of its cell (|offset| <= 1/2).
  // The 3-D fraction is the product over the axes.
  static double retainedMassFraction1D(double sharpness, int radius, double offset);

  // The window of a parcel at x with collision diameter `diameter` (read only with a parcel factor): +-R
  // cells around its cell, clipped to the background (fluid or not: the renormalisation over fluid cells is
  // the caller's, so isFluid is not read); orphan beyond R cells outside the box.
  template <class IsFluid>
  StencilResult window(const BackgroundGrid& g, const double* x, double diameter, const IsFluid&, Window& w) const {
    const double parcelLength = parcelFactor_ * diameter;
    for (int d = 0; d < 3; ++d) {
      double a = axisA_[d], expMinus2a = expMinus2a_[d];
      int r = r_;
      const double length = isotropicLength_ > 0.0 ? isotropicLength_ : g.spacing[d];
      if (parcelLength > length) {  // a parcel wider than the cell's kernel
        const double cellsPerLength = g.spacing[d] / parcelLength;
        a = a_ * cellsPerLength * cellsPerLength;
        expMinus2a = std::exp(-2.0 * a);
        r = std::min(maxRadius, static_cast<int>(std::ceil(r_ * parcelLength / length - 1e-9)));
      }
      double xi = (x[d] - g.origin[d]) / g.spacing[d];  // position in cell units
      // also rejects NaN: no stencil cell can exist beyond r cells outside the box
      if (!(xi > -r - 1.0 && xi < g.cells[d] + r + 1.0)) return StencilResult::orphan;
      // reflecting faces: a parcel and its mirror image have the same folded window
      if (reflect_) xi = foldIntoBox(xi, g.cells[d]);
      const int ic = std::min(static_cast<int>(std::floor(xi)), g.cells[d] - 1);
      const int lo = ic - r < 0 ? 0 : ic - r;
      const int hi = ic + r > g.cells[d] - 1 ? g.cells[d] - 1 : ic + r;
      if (lo > hi) return StencilResult::orphan;
      w.lo[d] = lo;
      w.n[d] = hi - lo + 1;
      // exp(-a t^2) at t = t0 + m, m = -r..r, from the centre outwards with 3 exponentials: the ratio of
      // neighbours is exp(-a (2 t + 1)) upwards, and each ratio is exp(-2a) times the previous one.
      // All ratios are <= 1 (|t0| <= 1/2), so far factors underflow to 0 as exp itself would.
      const double t0 = (ic + 0.5) - xi;
      double f[Window::maxWidth];
      f[r] = std::exp(-a * t0 * t0);
      double up = std::exp(-a * (2.0 * t0 + 1.0)), down = std::exp(-a * (1.0 - 2.0 * t0));
      for (int m = 1; m <= r; ++m) {
        f[r + m] = f[r + m - 1] * up;
        f[r - m] = f[r - m + 1] * down;
        up *= expMinus2a;
        down *= expMinus2a;
      }
      if (!reflect_) {
        for (int i = lo; i <= hi; ++i) w.f[d][i - lo] = f[i - ic + r];
        continue;
      }
      // Cells beyond a face add to their mirror cells (cell -1-m is the mirror of cell m): the image
      // parcel's weights. With ic inside the box every mirror cell lies in [lo, hi].
      for (int i = lo; i <= hi; ++i) w.f[d][i - lo] = 0.0;
      for (int m = -r; m <= r; ++m) w.f[d][mirrorCell(ic + m, g.cells[d]) - lo] += f[r + m];
    }
    return StencilResult::ok;
  }

 private:
  // x (cell units) mirrored at the faces 0 and n until it lies in [0, n]
  static double foldIntoBox(double x, int n) {
    while (x < 0.0 || x > n) x = x < 0.0 ? -x : 2.0 * n - x;
    return x;
  }
  // cell index mirrored at the faces until it lies in [0, n - 1]
  static int mirrorCell(int i, int n) {
    while (i < 0 || i >= n) i = i < 0 ? -1 - i : 2 * n - 1 - i;
    return i;
  }

  double a_;
  int r_;
  double axisA_[3], expMinus2a_[3];
  double isotropicLength_ = 0.0;  // h [m] of the cell_volume length scale; 0: the cell length per axis
  double parcelFactor_ = 0.0;     // lambda; 0: the cell's kernel for every parcel (eq. 8)
  bool reflect_ = false;          // the background's faces mirror the kernel instead of truncating it
};

}  // namespace parcelflow::coupling
